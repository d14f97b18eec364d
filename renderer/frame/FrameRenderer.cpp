#include "frame/FrameRenderer.h"

#include "core/Error.h"
#include "frame/GBufferDump.h"
#include "frame/Readback.h"
#include "passes/CompositePass.h"
#include "passes/DirectLightingPass.h"
#include "passes/DynamicShPass.h"
#include "passes/GBufferPass.h"
#include "passes/GiApplyPass.h"
#include "passes/GiUpsamplePass.h"
#include "passes/ProbeDebugPass.h"
#include "passes/ShadowPass.h"
#include "profile/VolumeLod.h"

#include <glm/gtc/constants.hpp>

namespace pb::render {

FrameSettings defaultFrameSettings(const scene::Scene& scene) {
    FrameSettings s;
    s.exposure = scene.exposure;
    s.ambientUp = scene.sky.radiance * (0.25f * glm::pi<float>());
    s.ambientDown = s.ambientUp * 0.3f; // light bounced off the ground is dimmer than the sky
    return s;
}

FrameRenderer::FrameRenderer(const scene::Scene& scene, const FrameSettings& settings,
                             const GiOptions& gi)
    : gpu_(scene), settings_(settings), quirks_(gl::detectDriverQuirks()),
      preExposed_(gi.profile.gi.guardExposure == profile::GiGuard::On) {
    passes_.push_back(std::make_unique<ShadowPass>());
    passes_.push_back(std::make_unique<GBufferPass>());
    if (gi.probes) {
        checkGiProfileSupported(gi.profile);
        probes_ = std::make_unique<GpuProbes>(*gi.probes, gi.scenario,
                                              profile::parseVolumeLod(gi.profile.gi.volumeLod));
        if (gi.profile.gi.dynamic == profile::GiDynamic::Sh)
            passes_.push_back(std::make_unique<DynamicShPass>(*probes_, gi.profile, scene));
        auto apply = std::make_unique<GiApplyPass>(*probes_, gi.profile);
        giApply_ = apply.get();
        giApply_->setCountPixels(gi.debugView == GiDebugView::VolumeCoverage);
        passes_.push_back(std::move(apply));
        if (gi.profile.gi.resolution != profile::GiResolution::Full) {
            auto upsample = std::make_unique<GiUpsamplePass>(gi.profile);
            upsample_ = upsample.get();
            passes_.push_back(std::move(upsample));
        }
    }
    settings_.indirectOnly = gi.probes && gi.debugView == GiDebugView::GiOnly;
    passes_.push_back(std::make_unique<DirectLightingPass>());
    if (gi.probes && (gi.debugView == GiDebugView::ProbesIrradiance ||
                      gi.debugView == GiDebugView::ProbesVisibility))
        passes_.push_back(std::make_unique<ProbeDebugPass>(
            *probes_, gi.debugView == GiDebugView::ProbesVisibility));
    passes_.push_back(std::make_unique<CompositePass>());
}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::render(const RenderView& view, FrameTimer* timer) {
    if (!targets_ || targets_->gbuffer.width() != view.width ||
        targets_->gbuffer.height() != view.height)
        targets_ = std::make_unique<FrameTargets>(view.width, view.height);
    lastView_ = view;
    FrameContext ctx{gpu_, view, settings_, programs_, *targets_, quirks_, {}, {}, timer};
    ctx.preExposure = preExposed_ ? preExposureScale(settings_.exposure) : 1.0f;
    lastPreExposure_ = ctx.preExposure;
    if (upsample_) upsample_->beginFrame(view, ctx);
    for (auto& pass : passes_) {
        TimedSection section(timer, pass->name());
        pass->execute(ctx);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
}

void FrameRenderer::resetGiHistory() {
    if (upsample_) upsample_->resetHistory();
}

image::Image8 FrameRenderer::readOutput() const {
    if (!targets_) throw Error("readOutput before any frame was rendered");
    return readRgba8(targets_->output);
}

image::ImageF FrameRenderer::readRadiance() const {
    if (!targets_) throw Error("readRadiance before any frame was rendered");
    image::ImageF img = readFloat(targets_->radiance);
    if (lastPreExposure_ != 1.0f) // gi.guard_exposure: back to scene units (exact, a power of 2)
        for (std::size_t i = 0; i < img.pixels.size(); ++i)
            if (i % 4 != 3) img.pixels[i] /= lastPreExposure_;
    return img;
}

void FrameRenderer::dumpGBuffer(const std::string& dir) {
    if (!targets_) throw Error("dumpGBuffer before any frame was rendered");
    writeGBufferDump(dir, *targets_, lastView_, programs_);
}

void FrameRenderer::presentToWindow(int w, int h) const {
    if (!targets_) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_->outputFbo.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    if (quirks_.windowBlitNeedsSrgbOff) glDisable(GL_FRAMEBUFFER_SRGB);
    glBlitFramebuffer(0, 0, targets_->output.desc().width, targets_->output.desc().height, 0, 0, w,
                      h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    if (quirks_.windowBlitNeedsSrgbOff) glEnable(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace pb::render
