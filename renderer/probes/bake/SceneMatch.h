#pragma once
// Is this probe file for this scene? A probe file from another scene renders, ranks and costs
// plausible-looking nonsense with no error (issue 25, item 6), so every command that takes a
// probe file together with a scene checks it.
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <string>

namespace pb::probes {

// The bake's input hash (bakeInputHash) recomputed from `scene` and the set's own volumes,
// scenarios and settings - everything else the hash covers travels in the file - and compared
// with the one the file carries. Both storage choices are tried: a sparse bake that stored
// every probe reads back as dense. Nodes marked dynamic now that the bake kept static still
// match (the same scene); the reverse does not (the probes lack them).
bool probeSetMatchesScene(const ProbeSet& set, const scene::Scene& scene);

// Throws `path: baked for another scene ...` unless the set matches `scene` or `force`.
void requireProbesForScene(const std::string& path, const ProbeSet& set,
                           const scene::Scene& scene, bool force);

} // namespace pb::probes
