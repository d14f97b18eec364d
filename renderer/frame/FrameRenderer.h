#pragma once
// Builds the pass list and runs frames: [shadow] -> gbuffer -> [gi-dynamic-sh] -> [gi-apply ->
// [upsample]] -> direct -> composite (upsample only at gi.resolution half/quarter). Owns the
// scene's GPU resources, the probes' GPU copy, the program cache and the render targets
// (re-created when the resolution changes). Requires a current GL context (platforms/).
// Without probes there is no GI pass and no GI resource at all.
// Only what the scene and profile need is built (frame/FrameSkips.h: no shadow pass without a
// shadow-casting light, no SH pass without dynamic objects, no textures for omitted volumes),
// and a frame whose view sees no loaded volume runs no GI pass (renderer/README.md).
#include "frame/FrameSkips.h"
#include "frame/GiMemory.h"
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

// Defaults derived from the scene: its exposure, and an ambient of the sky's irradiance times
// the share of the sky its surfaces see (Sky::visibility) from above, less from below: the
// indirect light of pixels no probe volume covers, and of frames without GI.
FrameSettings defaultFrameSettings(const scene::Scene& scene);

// Baked probes for the GI apply pass; the set is only read during construction (uploaded).
struct GiOptions {
    const probes::ProbeSet* probes = nullptr; // null: no GI
    int scenario = 0;
    profile::Profile profile;
    GiDebugView debugView = GiDebugView::None; // --debug; volume_coverage turns counting on
};

class GiApplyPass;
class DynamicShPass;

struct FrameBuild {
    // false: build every pass the scene and profile name and run the GI passes on every frame,
    // even where they add nothing (tests check that skipping changes no pixel).
    bool skipUnneeded = true;
};

class FrameRenderer {
public:
    FrameRenderer(const scene::Scene& scene, const FrameSettings& settings,
                  const GiOptions& gi = {}, const FrameBuild& build = {});
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

    // Passes and resources left out at construction, one entry each (render --verbose).
    const std::vector<SkippedWork>& skipped() const { return skipped_; }
    // The last frame ran no GI pass: no loaded volume was in its view frustum (the lighting
    // took its no-GI path; probe textures and targets stay allocated for the next frame).
    bool giSkippedLastFrame() const { return giSkipped_; }
    // GPU memory of the GI as allocated so far (targets exist after the first frame).
    GiMemory giMemory() const;

private:
    bool anyVolumeVisible(const RenderView& view) const;

    GpuScene gpu_;
    FrameSettings settings_;
    gl::ProgramCache programs_;
    gl::DriverQuirks quirks_;
    std::unique_ptr<GpuProbes> probes_;
    std::unique_ptr<FrameTargets> targets_;
    std::vector<std::unique_ptr<Pass>> passes_;
    GiApplyPass* giApply_ = nullptr;
    GiUpsamplePass* upsample_ = nullptr; // owned by passes_
    DynamicShPass* dynamicSh_ = nullptr; // owned by passes_
    std::vector<SkippedWork> skipped_;
    bool skipGiWhenUnseen_ = false, giSkipped_ = false;
    RenderView lastView_;
    bool preExposed_ = false;      // gi.guard_exposure
    float lastPreExposure_ = 1.0f; // the last frame's FrameContext::preExposure
};

} // namespace pb::render
