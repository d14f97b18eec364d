#include "stress/gl/GlStressRenderer.h"

#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "frame/Readback.h"
#include "gl/Capabilities.h"
#include "passes/GiApplyPass.h"
#include "stress/StressCases.h"

#include <algorithm>

namespace pb::stress {

const probes::ProbeSet& GlStressRenderer::probesFor(const CaseData& data, probes::StorageFormat f) {
    if (cached_ != data.id || data.id == 0) {
        sets_.clear();
        cached_ = data.id;
    }
    auto it = sets_.find(f);
    if (it == sets_.end()) it = sets_.emplace(f, inStorageFormat(data.probes, f)).first;
    return it->second;
}

RenderedFrame GlStressRenderer::render(const CaseData& data, const StressVariant& variant) {
    const std::uint64_t mark = debug_.mark();
    render::FrameSettings settings = render::defaultFrameSettings(data.scene);
    settings.exposure = data.exposure;
    render::GiOptions gi;
    gi.probes = &probesFor(data, variant.storage);
    gi.profile = variant.profile;
    RenderedFrame out;
    {
        render::FrameRenderer r(data.scene, settings, gi);
        r.render(
            render::makeRenderView(data.view, data.scene.worldBounds(), data.width, data.height));
        out.radiance = r.readRadiance();
        if (readOutput_) out.output = r.readOutput();
        if (const render::GiApplyPass* pass = r.giApplyPass())
            out.nonfiniteGiTexels = countNonfinitePixels(render::readFloat(*pass->target()));
    }
    if (auto errors = debug_.errorsSince(mark); !errors.empty())
        throw Error("the GL reported " + std::to_string(errors.size()) +
                    " error(s): " + gl::DebugOutput::format(errors.front()));
    return out;
}

int largestStressResolution(int limit) {
    const gl::GlCaps caps = gl::queryCaps();
    return std::max(1, std::min({limit, caps.maxRenderbufferSize, caps.maxTextureSize}));
}

} // namespace pb::stress
