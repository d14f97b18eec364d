#include "frame/FrameRenderer.h"

#include "core/Error.h"
#include "frame/GBufferDump.h"
#include "frame/Readback.h"
#include "passes/CompositePass.h"
#include "passes/DirectLightingPass.h"
#include "passes/DynamicObjects.h"
#include "passes/DynamicShPass.h"
#include "passes/GBufferPass.h"
#include "passes/GiApplyPass.h"
#include "passes/GiUpsamplePass.h"
#include "passes/GiVolumeRaster.h"
#include "passes/ProbeDebugPass.h"
#include "passes/ShadowPass.h"
#include "profile/VolumeLod.h"

#include <glm/gtc/constants.hpp>

namespace pb::render {

FrameSettings defaultFrameSettings(const scene::Scene& scene) {
    FrameSettings s;
    s.exposure = scene.exposure;
    // The sky's irradiance on an open upward surface (pi L) times the share of the sky the
    // scene's surfaces see: a closed interior is not lit like an open square.
    s.ambientUp = scene.sky.radiance * (glm::pi<float>() * scene.sky.visibility);
    s.ambientDown = s.ambientUp * 0.3f; // light bounced off the ground is dimmer than the sky
    return s;
}

FrameRenderer::FrameRenderer(const scene::Scene& scene, const FrameSettings& settings,
                             const GiOptions& gi, const FrameBuild& build)
    : gpu_(scene), settings_(settings), quirks_(gl::detectDriverQuirks()),
      preExposed_(gi.profile.gi.guardExposure == profile::GiGuard::On) {
    const bool lean = build.skipUnneeded;
    // The shadow pass returned early without a sun anyway (and allocated nothing): now it is
    // not built, and the lighting's sun term stays off exactly as before.
    if (std::string why = shadowSkipReason(scene); lean && !why.empty())
        skipped_.push_back({"pass shadow (no shadow map)", why});
    else
        passes_.push_back(std::make_unique<ShadowPass>());
    passes_.push_back(std::make_unique<GBufferPass>());
    if (gi.probes) {
        profile::Profile prof = gi.profile;
        if (std::string why = dynamicShSkipReason(scene, prof); lean && !why.empty()) {
            skipped_.push_back({"pass gi-dynamic-sh", why});
            prof.gi.dynamic = profile::GiDynamic::PerPixel;
        }
        probes_ = std::make_unique<GpuProbes>(*gi.probes, gi.scenario,
                                              profile::parseVolumeLod(prof.gi.volumeLod),
                                              prof.gi.technique, prof.gi.shLeak);
        // A technique whose probes the projection cannot read (SH: no DDGI textures) lights
        // dynamic objects with its per-pixel lookup instead.
        if (std::string why = probes_->technique().dynamicShUnsupported();
            prof.gi.dynamic == profile::GiDynamic::Sh && !why.empty()) {
            skipped_.push_back(
                {"pass gi-dynamic-sh", "gi.technique=" + prof.get("gi.technique") + " " + why});
            prof.gi.dynamic = profile::GiDynamic::PerPixel;
        }
        std::vector<int> kept;
        for (const GpuProbeVolume& v : probes_->volumes())
            kept.push_back(v.fileIndex);
        for (SkippedWork& w : omittedVolumes(*gi.probes, kept, prof.gi.volumeLod))
            skipped_.push_back(std::move(w));
        if (prof.gi.dynamic == profile::GiDynamic::Sh) {
            auto sh = std::make_unique<DynamicShPass>(*probes_, prof, scene);
            dynamicSh_ = sh.get();
            passes_.push_back(std::move(sh));
        }
        auto apply = std::make_unique<GiApplyPass>(*probes_, prof,
                                                   !findDynamicObjects(scene).objects.empty());
        giApply_ = apply.get();
        giApply_->setCountPixels(gi.debugView == GiDebugView::VolumeCoverage);
        passes_.push_back(std::move(apply));
        if (prof.gi.resolution != profile::GiResolution::Full) {
            auto upsample = std::make_unique<GiUpsamplePass>(prof);
            upsample_ = upsample.get();
            passes_.push_back(std::move(upsample));
        }
        // Per frame, a view that sees no volume skips the GI passes. Not with the SH pass (an
        // object's centre may lie in a volume the view does not see) nor under a debug view
        // (they show the GI passes' work).
        skipGiWhenUnseen_ = lean && !dynamicSh_ && gi.debugView == GiDebugView::None;
    } else {
        skipped_.push_back({"GI passes", "no probes (render --probes FILE)"});
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

// The apply pass's own culling test (GiVolumeRaster: all 8 corners beyond one clip plane),
// which does not depend on the GI target's size.
bool FrameRenderer::anyVolumeVisible(const RenderView& view) const {
    const glm::ivec2 size(view.width, view.height);
    for (const GpuProbeVolume& v : probes_->volumes())
        if (volumeRaster(v, view, size, 1, size).visible) return true;
    return false;
}

void FrameRenderer::render(const RenderView& view, FrameTimer* timer) {
    if (!targets_ || targets_->gbuffer.width() != view.width ||
        targets_->gbuffer.height() != view.height)
        targets_ = std::make_unique<FrameTargets>(view.width, view.height);
    lastView_ = view;
    // All volumes culled: the apply pass would clear its target to weight 0 and draw nothing,
    // and the lighting would add 0 + 1 x ambient - exactly its no-GI path, taken instead.
    giSkipped_ = skipGiWhenUnseen_ && !anyVolumeVisible(view);
    FrameContext ctx{gpu_, view, settings_, programs_, *targets_, quirks_, {}, {}, timer};
    ctx.preExposure = preExposed_ ? preExposureScale(settings_.exposure) : 1.0f;
    lastPreExposure_ = ctx.preExposure;
    if (upsample_) {
        if (giSkipped_)
            upsample_->resetHistory(); // the history misses the skipped frames
        else
            upsample_->beginFrame(view, ctx);
    }
    for (auto& pass : passes_) {
        if (giSkipped_ && (pass.get() == giApply_ || pass.get() == upsample_)) continue;
        TimedSection section(timer, pass->name());
        pass->execute(ctx);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
}

GiMemory FrameRenderer::giMemory() const {
    GiMemory m;
    if (probes_) m.probes = probes_->bytes();
    if (giApply_) m.evaluation = giApply_->targetBytes();
    if (upsample_) m.upsample = upsample_->bytes();
    if (dynamicSh_) m.dynamicSh = dynamicSh_->bytes();
    return m;
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
