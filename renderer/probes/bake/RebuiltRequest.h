#pragma once
// The bake request a probe set was baked from, rebuilt from the set itself: its volumes,
// scenarios, settings and free-space record, with the one thing the file does not say (whether
// storage was sparse) found by trying both. Proved by the input hash: the rebuilt request
// hashes to the set's own (BakeHash.cpp), so baking it again with other bounces changes
// nothing else. `bench --truth` bakes "one fewer bounce pass" this way (issue 43).
#include "probes/ProbeSet.h"
#include "probes/bake/Baker.h"
#include "scene/Scene.h"

#include <optional>
#include <string>

namespace pb::probes {

// The request whose bakeInputHash(scene, request) is set.inputHash, or nothing with `why`
// saying so (the set was baked for another scene or by an older bake). SceneMatch.h asks it
// whether a probe file belongs to a scene.
std::optional<BakeRequest> rebuiltBakeRequest(const scene::Scene& scene, const ProbeSet& set,
                                              std::string* why = nullptr);

} // namespace pb::probes
