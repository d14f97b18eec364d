#pragma once
// The lighting-independent part of a probe, done once for all scenarios: relocation,
// classification and visibility.
//
// Classification: a ray "hits a back face" when it hits the back of a SINGLE-sided triangle
// (double-sided geometry has no inside). A probe whose back-face ratio exceeds the threshold
// (default 0.25) is inside geometry: invalid, excluded by the sampler, not traced again.
// Relocation (optional), up to kMaxRelocationIterations times:
//   - back-face ratio above the threshold: step through the closest back face
//     (its distance + kRelocationClearance * minCell);
//   - else, closest front face nearer than kRelocationClearance * minCell: step away from it
//     to that clearance;
//   - else stop. The offset is clamped to +-kMaxRelocation cell per local axis and, in a
//     child volume, to the box (a probe on a face moves only inwards, and steps only through
//     back faces that lead inwards); the probe is classified where it ends.
// Visibility: the final position's rays; distance min(t, maxDistance) / maxDistance, a miss
// counts as 1 (see ProbeConvolution.h).
#include "probes/bake/ProbeConvolution.h"
#include "probes/ProbeSet.h"
#include "raytrace/RayScene.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

constexpr int kMaxRelocationIterations = 3;
constexpr float kRelocationClearance = 0.2f;

struct GeometryScratch {
    std::vector<raytrace::RayHit> hits;         // per ray, before classification
    std::vector<glm::vec3> worldDirs; // per ray, the direction traced
    std::vector<float> t;             // hit distance per ray (inf = miss)
    std::vector<char> backface;       // per ray
    std::vector<float> dist01;        // per ray
};

// Computes `state` (offset, validity, ratio) and, for a valid probe, the 14x14 visibility
// interior (mean, meanSq per texel) into visOut. `rays` counts rays traced.
void bakeProbeGeometry(const raytrace::RayScene& rs, const ProbeVolume& vol, const glm::ivec3& c,
                       const std::vector<glm::vec3>& localDirs, const ProbeConvolution& conv,
                       const BakeSettings& settings, GeometryScratch& scratch, ProbeState& state,
                       float* visOut, std::uint64_t& rays);

} // namespace pb::probes
