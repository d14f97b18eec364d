#pragma once
// The GPU memory the GI of a frame holds, split by owner: the probe textures gi.volume_lod
// keeps, the apply pass's evaluation target (+ its depth-stencil under gi.multi_volume=stencil),
// the upsample pass's full-resolution output (a ping-pong pair with surface records under
// gi.upsample=temporal) and the dynamic-object SH textures (gi.dynamic=sh with dynamic
// objects). `probebench tune` budgets this total.
//
// Two ways to get it, cross-checked by tests/gl/FrameSkipTest.cpp: FrameRenderer::giMemory()
// sums the textures a rendered frame allocated; estimateGiMemory() computes the same bytes
// from the profile, the probe set and the output size without GL (so a search can drop
// candidates over a memory budget before rendering them). The pixel-counting attachment of
// `render --verbose` is a diagnostic and not counted by the estimate.
#include "probes/ProbeSet.h"
#include "profile/Profile.h"

#include <cstddef>

namespace pb::render {

struct GiMemory {
    std::size_t probes = 0;     // probe textures of the kept volumes, one scenario
    std::size_t evaluation = 0; // GI target (gi.resolution, gi.target_format) + depth-stencil
    std::size_t upsample = 0;   // full-resolution upsample output / temporal history
    std::size_t dynamicSh = 0;  // gi.dynamic=sh textures
    std::size_t total() const { return probes + evaluation + upsample + dynamicSh; }
    double totalMiB() const { return double(total()) / (1024.0 * 1024.0); }
};

// What a FrameRenderer built with these inputs allocates after its first frame at
// width x height. Throws pb::Error when gi.volume_lod cannot be applied to the set.
GiMemory estimateGiMemory(const profile::Profile& p, const probes::ProbeSet& set, int width,
                          int height, int dynamicObjects);

} // namespace pb::render
