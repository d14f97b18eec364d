#pragma once
// Incremental probe updates on the GPU (issue 20): re-uploads only the irradiance tiles of
// the probes that changed (one glTexSubImage3D of an 8x8 tile each, border included), not
// the whole texture. Dense volumes in RGBA16F or RGBA32F only (throws pb::Error otherwise).
// Requires a current GL context.
#include "passes/GpuProbes.h"
#include "probes/ProbeSet.h"

#include <cstddef>
#include <vector>

namespace pb::render {

struct ProbeTile {
    int volume = 0; // index in the probe set
    int probe = 0;
};

// Uploads the tiles of `tiles` from set.irradiance[scenario] (their `texels`, encoded as the
// GPU copy stores them); returns the bytes uploaded. Volumes the GPU copy left out are skipped.
std::size_t uploadProbeTiles(const GpuProbes& gpu, const probes::ProbeSet& set, int scenario,
                             const std::vector<ProbeTile>& tiles);

} // namespace pb::render
