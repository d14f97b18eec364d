#pragma once
#include "scene/Scene.h"

namespace pb::scene {

// The "default" view every scene gets first, from its static bounds alone (no scene-specific
// knowledge, any scale, any offset from the origin). See DefaultView.cpp for the rule.
View makeDefaultView(const Bounds& staticBounds);

// `base`, or `base_2`, `base_3`, ... whichever no view of `scene` uses yet.
std::string uniqueViewName(const Scene& scene, const std::string& base);

} // namespace pb::scene
