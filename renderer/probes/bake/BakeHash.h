#pragma once
// The first part of the bake's input hash (bakeInputHash, Baker.h): the bake's algorithm
// version, the probe file version and the scene as the bake sees it (materials, static
// geometry, lights). Exposed so the placement's cache key (placement/PlacementKey.h) hashes
// the scene exactly as the bake does: a scene edit that re-bakes also re-places.
#include "core/Hash.h"
#include "probes/ProbeVolume.h"
#include "scene/Scene.h"

namespace pb::probes {

void hashBakeVersionsAndScene(Hasher& h, const scene::Scene& scene);
// Every field of one volume (ProbeVolume::forEachField), as the bake's input hash takes it.
void hashVolume(Hasher& h, const ProbeVolume& v);

} // namespace pb::probes
