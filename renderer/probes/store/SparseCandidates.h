#pragma once
// Probes a sparse layout would not need to store (the file and the GPU still store every
// probe; README.md "Sparse storage" says what storing only the others would take):
//   far     - valid, but its visibility says no surface within maxDistance (1.5 cell
//             diagonals) in any direction: every interior texel's mean distance is at least
//             kFarVisibility of the clamp. A surface point only ever samples the 8 probes of
//             its cell, all within one cell diagonal, so no surface shading reads a far probe
//             (dynamic objects in mid-air still would).
//   invalid - inside geometry (the bake's back-face test); the sampler skips it already.
// Computed from the baked visibility alone (no scene needed). The rays are finite: a very
// thin object between two ray directions can be missed, so these are candidates.
#include "probes/ProbeSet.h"

#include <vector>

namespace pb::probes {

constexpr float kFarVisibility = 0.98f; // of maxDistance; leaves room for BC6H's error

struct SparseCounts {
    std::size_t far = 0, invalid = 0;
    std::size_t total() const { return far + invalid; }
};

// One entry per volume of the set.
std::vector<SparseCounts> countSparseCandidates(const ProbeSet& set);

// True when every interior visibility texel of probe `c` reads >= kFarVisibility.
bool probeSeesNoSurface(const ProbeTexture& visibility, const glm::ivec3& c);

} // namespace pb::probes
