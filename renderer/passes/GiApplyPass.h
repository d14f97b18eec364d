#pragma once
// GI apply: evaluates the probe irradiance for every GBuffer pixel into the GI evaluation
// target (gi.resolution, gi.target_format) and hands it to the lighting through
// FrameContext::gi. The lookup is the probes' technique's (GpuProbes::technique(): its
// applyShader(), gi_ddgi_apply.frag with common_ddgi.glsl or, under gi.technique=sh_l1|sh_l2,
// common_sh.glsl; its textures bound by GpuProbes::bindVolume); the target, the culling, the
// draws and the stencil path below are every technique's. Volumes outside the view frustum
// are culled; the rest are drawn per gi.multi_volume:
//   naive:   largest first, full-screen, each overwriting (the last draw = smallest volume);
//   stencil: smallest first, one stencil bit ('taken') on a depth-stencil of the GI target's
//            size, so each pixel is evaluated once, by the smallest volume containing it;
//            per volume an apply that writes no stencil (so the test runs before the
//            shader), then a cheap mark draw; with the eye inside the box the depth test
//            decides the influence and the apply marks itself (renderer/README.md
//            "gi.multi_volume=stencil").
#include "gl/Capabilities.h"
#include "passes/FrameContext.h"
#include "passes/GiInvocationCounter.h"
#include "passes/GiPassStats.h"
#include "passes/GiTargets.h"
#include "passes/GiVolumeRaster.h"
#include "passes/GpuProbes.h"
#include "profile/Profile.h"

namespace pb::render {

// Every define a GI shader variant gets from the profile (SwitchTable) plus the sampler's
// constants (DDGI_*), plus DDGI_SPARSE_TILES when `probes` (the set it will sample) has a
// sparse volume: the indirection's integer arithmetic is compiled only where data needs it.
gl::Defines giShaderDefines(const profile::Profile& p, const GpuProbes* probes = nullptr);
gl::TextureFormat giTargetFormat(profile::GiTargetFormat f);
// Throws pb::Error naming the switch when the context cannot render to the profile's GI target
// format (ES 3.0 guarantees none of the float formats; a weak GPU may lack one).
void requireRenderableTarget(const profile::Profile& profile, const gl::GlCaps& caps);

class GiApplyPass : public Pass {
public:
    static constexpr int kFirstProbeUnit = 5;     // after the GBuffer's channels and depth
    static constexpr unsigned kStencilTaken = 1u; // stencil: a smaller volume shaded the pixel

    // dynamicObjects: the scene has dynamic objects. With gi.dynamic=per_pixel their pixels are
    // then looked up without the behind-surface fade (GI_DYNAMIC_UNFADED: one flags fetch per
    // pixel, so scenes without them keep the shader as it was).
    GiApplyPass(const GpuProbes& probes, const profile::Profile& profile,
                bool dynamicObjects = false);
    const char* name() const override { return "gi-apply"; }
    void execute(FrameContext& frame) override;
    const gl::Texture* target() const { return targets_.target(); }
    std::size_t targetBytes() const { return targets_.bytes(); }

    // Diagnostics: count the pixels each volume evaluates (a read-back per volume; slow), and
    // where the context has atomic counters the fragment-shader invocations of each volume's
    // apply and mark draws (GiInvocationCounter; the shaders' GI_COUNT_INVOCATIONS).
    void setCountPixels(bool on) { countPixels_ = on; }
    // Measurement only: count the apply with the tests the counter forces (no
    // early_fragment_tests) instead of the production shader's (README "Invocation counter").
    void setCountInvocationsWithLateTests(bool on) { countLate_ = on; }
    // Test-only: off draws every volume in the frustum over the whole target, as before the
    // draws were scissored to their box's rectangle and an off-screen box skipped
    // (GiVolumeRaster::screenRect; GiScreenRectTest compares the two).
    void setScreenRects(bool on) { screenRects_ = on; }
    const GiPassStats& stats() const { return stats_; }

private:
    struct Draw; // one frame's shared state (GiApplyPass.cpp)
    void drawNaive(Draw& d, int v);
    void drawStencil(Draw& d, int v, const GiVolumeRaster& r, bool last, bool countInvocations);
    void countEvaluated(int statsIndex);

    const GpuProbes& probes_;
    profile::Profile profile_;
    gl::Defines defines_;
    bool countPixels_ = false;
    bool countLate_ = false;
    bool screenRects_ = true;
    GiInvocationCounter invocations_;
    GiTargets targets_;
    GiPassStats stats_;
};

} // namespace pb::render
