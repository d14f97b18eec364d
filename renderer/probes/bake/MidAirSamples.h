#pragma once
// Random points in the free space of the probe volumes: where dynamic objects stand and what
// sparse storage's fill (AbsentProbeFill.h) must light (issue 18). Uniform over the root
// volumes' boxes (a box picked by its volume), skipping points inside geometry - one of 32
// rays over the sphere reaches the back of a single-sided triangle first - and points sealed
// in (every one of the 32 rays hits within `sealedBelow`: inside a double-sided solid, which
// has no back face, or in a gap no object fits). Deterministic for a given seed.
#include "probes/ProbeVolume.h"
#include "raytrace/RayScene.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// True when the point lies inside geometry or is sealed in (the tests above).
bool insideGeometry(const raytrace::RayScene& rs, const glm::vec3& p, float sealedBelow);

// Up to `count` points (fewer when most of the boxes are solid: 8 * count tries).
std::vector<glm::vec3> midAirSamples(const raytrace::RayScene& rs, const std::vector<ProbeVolume>& volumes,
                                     int count, float sealedBelow,
                                     std::uint64_t seed = 0xA1125EEDu);

} // namespace pb::probes
