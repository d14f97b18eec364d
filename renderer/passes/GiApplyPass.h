#pragma once
// GI apply (DDGI): evaluates the probe irradiance for every GBuffer pixel into the GI
// evaluation target (gi.resolution, gi.target_format), one draw per loaded probe volume in
// GpuProbes::drawOrder (gi.multi_volume = naive), and hands the target to the lighting through
// FrameContext::gi. Shader: gi_ddgi_apply.frag + common_ddgi.glsl.
#include "passes/FrameContext.h"
#include "passes/GpuProbes.h"
#include "profile/Profile.h"

#include <memory>

namespace pb::render {

// Every define a GI shader variant gets from the profile (SwitchTable) plus the sampler's
// constants (DDGI_*).
gl::Defines giShaderDefines(const profile::Profile& p);
gl::TextureFormat giTargetFormat(profile::GiTargetFormat f);

// Throws pb::Error when the profile asks for a switch value this pass does not implement yet.
void checkGiProfileSupported(const profile::Profile& p);

class GiApplyPass : public Pass {
public:
    static constexpr int kFirstProbeUnit = 5; // after the GBuffer's channels and depth

    GiApplyPass(const GpuProbes& probes, const profile::Profile& profile);
    const char* name() const override { return "gi-apply"; }
    void execute(FrameContext& frame) override;
    const gl::Texture* target() const { return target_.get(); }

private:
    const GpuProbes& probes_;
    profile::Profile profile_;
    gl::Defines defines_;
    std::unique_ptr<gl::Texture> target_;
    std::unique_ptr<gl::Framebuffer> fbo_;
};

} // namespace pb::render
