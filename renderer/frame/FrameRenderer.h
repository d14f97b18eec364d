#pragma once
// Builds the pass list and runs frames: shadow -> gbuffer -> [gi-dynamic-sh] -> [gi-apply ->
// [upsample]] -> direct -> composite (upsample only at gi.resolution half/quarter). Owns the
// scene's GPU resources, the probes' GPU copy, the program cache and the render targets
// (re-created when the resolution changes). Requires a current GL context (platforms/).
// Without probes there is no GI pass and no GI resource at all.
#include "image/Image.h"
#include "passes/FrameContext.h"
#include "passes/GiDebugView.h"
#include "passes/GpuProbes.h"
#include "probes/ProbeSet.h"
#include "profile/Profile.h"

#include <memory>
#include <string>
#include <vector>

namespace pb::render {

class GiUpsamplePass;

// Defaults derived from the scene: its exposure, and an ambient of a quarter of the sky's
// irradiance from above, less from below (a crude stand-in for sky visibility until the GI
// passes fill the indirect input).
FrameSettings defaultFrameSettings(const scene::Scene& scene);

// Baked probes for the GI apply pass; the set is only read during construction (uploaded).
struct GiOptions {
    const probes::ProbeSet* probes = nullptr; // null: no GI
    int scenario = 0;
    profile::Profile profile;
    GiDebugView debugView = GiDebugView::None; // --debug; volume_coverage turns counting on
};

class GiApplyPass;

class FrameRenderer {
public:
    FrameRenderer(const scene::Scene& scene, const FrameSettings& settings,
                  const GiOptions& gi = {});
    ~FrameRenderer();

    // One frame; with a timer, every pass is a timed section named by Pass::name().
    void render(const RenderView& view, FrameTimer* timer = nullptr);

    image::Image8 readOutput() const;   // tonemapped sRGB, 8-bit
    image::ImageF readRadiance() const; // linear HDR radiance (RGBA, alpha = 1), scene units
    // Writes every GBuffer channel (PNG for colours and normals, PFM for HDR and depth).
    void dumpGBuffer(const std::string& dir);
    // Copies the output to the default framebuffer of a window of size w x h.
    void presentToWindow(int w, int h) const;

    const std::vector<std::unique_ptr<Pass>>& passes() const { return passes_; }
    FrameSettings& settings() { return settings_; }
    gl::ProgramCache& programs() { return programs_; }
    const FrameTargets* targets() const { return targets_.get(); }
    const GpuProbes* gpuProbes() const { return probes_.get(); } // null without GI
    GiApplyPass* giApplyPass() const { return giApply_; }        // null without GI
    // gi.upsample=temporal: the next frame starts a fresh GI history (a camera cut the caller
    // knows about; sudden jumps are also detected). No effect without an upsample pass.
    void resetGiHistory();
    const GiUpsamplePass* giUpsample() const { return upsample_; } // null at full resolution

private:
    GpuScene gpu_;
    FrameSettings settings_;
    gl::ProgramCache programs_;
    gl::DriverQuirks quirks_;
    std::unique_ptr<GpuProbes> probes_;
    std::unique_ptr<FrameTargets> targets_;
    std::vector<std::unique_ptr<Pass>> passes_;
    GiApplyPass* giApply_ = nullptr;
    GiUpsamplePass* upsample_ = nullptr; // owned by passes_
    RenderView lastView_;
    bool preExposed_ = false;      // gi.guard_exposure
    float lastPreExposure_ = 1.0f; // the last frame's FrameContext::preExposure
};

} // namespace pb::render
