#pragma once
#include "scene/Scene.h"

namespace pb::scene {

// The "default" view every scene gets first, for any scale and any offset from the origin.
// From the static bounds alone: inside them at 30% of their height, 15% in from the + end of
// the longest horizontal axis, looking back along it about 8 degrees down.
View makeDefaultView(const Bounds& staticBounds);
// The same rule, then checked against the static geometry with a few CPU rays: if that eye
// is in or against something or the view is blocked, the nearest pose (in a fixed search
// order) that sees well. See DefaultView.cpp.
View makeDefaultView(const Scene& scene);

// `base`, or `base_2`, `base_3`, ... whichever no view of `scene` uses yet.
std::string uniqueViewName(const Scene& scene, const std::string& base);

} // namespace pb::scene
