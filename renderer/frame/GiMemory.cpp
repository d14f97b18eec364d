#include "frame/GiMemory.h"

#include "gl/TextureFormat.h"
#include "passes/DynamicShPass.h"
#include "passes/GiApplyPass.h"
#include "passes/GpuTechnique.h"
#include "profile/GiVolumeLod.h"
#include "profile/VolumeLod.h"

#include <algorithm>

namespace pb::render {

GiMemory estimateGiMemory(const profile::Profile& p, const probes::ProbeSet& set, int width,
                          int height, int dynamicObjects) {
    GiMemory m;
    const std::unique_ptr<GpuTechnique> technique = makeGpuTechnique(p.gi.technique, p.gi.shLeak);
    for (int v : profile::selectVolumes(set, profile::parseVolumeLod(p.gi.volumeLod)))
        m.probes += technique->volumeBytes(set, v);
    // GiApplyPass::execute: the target at size / divisor (at least 1 texel per axis).
    const int div = profile::resolutionDivisor(p.gi.resolution);
    const int w = std::max(1, width / div), h = std::max(1, height / div);
    const gl::TextureFormat format = giTargetFormat(p.gi.targetFormat);
    m.evaluation = gl::textureBytes(format, w, h);
    if (p.gi.multiVolume == profile::GiMultiVolume::Stencil)
        m.evaluation += gl::textureBytes(gl::TextureFormat::Depth32FStencil8, w, h);
    // GiUpsamplePass: one full-size target; temporal keeps two, each with a surface record.
    if (div != 1) {
        if (p.gi.upsample == profile::GiUpsample::Temporal)
            m.upsample = 2 * (gl::textureBytes(format, width, height) +
                              gl::textureBytes(gl::TextureFormat::RGBA16F, width, height));
        else
            m.upsample = gl::textureBytes(format, width, height);
    }
    // DynamicShPass (FrameRenderer turns it off under a technique it cannot project, as SH):
    // directions, positions, lookups (kDirections x objects), weights (kDirections x 1),
    // coefficients (4 x objects), all RGBA32F.
    if (p.gi.dynamic == profile::GiDynamic::Sh && dynamicObjects > 0 &&
        technique->dynamicShUnsupported().empty()) {
        const int rows = dynamicObjects, n = DynamicShPass::kDirections;
        const auto rgba32f = [](int tw, int th) {
            return gl::textureBytes(gl::TextureFormat::RGBA32F, tw, th);
        };
        m.dynamicSh = 3 * rgba32f(n, rows) + rgba32f(n, 1) + rgba32f(4, rows);
    }
    return m;
}

} // namespace pb::render
