#include "passes/GiApplyPass.h"

#include "core/Error.h"
#include "profile/SwitchTable.h"

namespace pb::render {

gl::Defines giShaderDefines(const profile::Profile& p) {
    gl::Defines d = ddgiConstantDefines();
    for (const auto& [name, value] : profile::shaderDefines(p))
        d[name] = value;
    return d;
}

gl::TextureFormat giTargetFormat(profile::GiTargetFormat f) {
    switch (f) {
    case profile::GiTargetFormat::Rgba32f:
        return gl::TextureFormat::RGBA32F;
    case profile::GiTargetFormat::R11g11b10f:
        return gl::TextureFormat::R11G11B10F;
    case profile::GiTargetFormat::Rgba16f:
        break;
    }
    return gl::TextureFormat::RGBA16F;
}

void checkGiProfileSupported(const profile::Profile& p) {
    auto unsupported = [](const std::string& what) {
        throw Error(what + " is not implemented yet (issue 4); use the default");
    };
    if (p.gi.precision != profile::GiPrecision::Fp32) unsupported("gi.precision=fp16");
    if (p.gi.multiVolume != profile::GiMultiVolume::Naive) unsupported("gi.multi_volume=stencil");
    if (p.gi.dynamic != profile::GiDynamic::PerPixel) unsupported("gi.dynamic=sh");
}

GiApplyPass::GiApplyPass(const GpuProbes& probes, const profile::Profile& profile)
    : probes_(probes), profile_(profile), defines_(giShaderDefines(profile)) {
    checkGiProfileSupported(profile);
}

void GiApplyPass::execute(FrameContext& frame) {
    const int div = profile::resolutionDivisor(profile_.gi.resolution);
    const GBuffer& gb = frame.targets.gbuffer;
    const int w = std::max(1, gb.width() / div), h = std::max(1, gb.height() / div);
    if (!target_ || target_->desc().width != w || target_->desc().height != h) {
        gl::TextureDesc d;
        d.format = giTargetFormat(profile_.gi.targetFormat);
        d.width = w;
        d.height = h;
        // Full resolution is read with texelFetch; lower ones are upsampled bilinearly.
        d.filter = div == 1 ? gl::Filter::Nearest : gl::Filter::Linear;
        fbo_.reset();
        target_ = std::make_unique<gl::Texture>(d);
        fbo_ = std::make_unique<gl::Framebuffer>(
            "gi evaluation", std::vector<const gl::Texture*>{target_.get()}, nullptr);
    }
    fbo_->bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0); // weight 0 = no volume: the lighting falls back to its ambient
    glClear(GL_COLOR_BUFFER_BIT);

    const gl::Program& prog = frame.programs.get("fullscreen.vert", "gi_ddgi_apply.frag", defines_);
    prog.use();
    gb.bindForReading(prog, 0);
    prog.set("u_relFromClip", frame.view.relFromClip);
    prog.set("u_gbufferInvSize", glm::vec2(1.0f / float(gb.width()), 1.0f / float(gb.height())));
    prog.set("u_giDivisor", div);
    prog.set("u_giJitter", frame.giJitter); // gi.upsample: where in the footprint to sample
    prog.set("u_ambientUp", frame.settings.ambientUp);
    prog.set("u_ambientDown", frame.settings.ambientDown);
    for (int v : probes_.drawOrder()) {
        probes_.bindVolume(prog, v, kFirstProbeUnit, frame.view.eye);
        drawFullscreenTriangle(frame.targets);
    }
    for (int u = kFirstProbeUnit + GpuProbes::kUnitsPerVolume - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    frame.gi.enabled = true;
    frame.gi.irradiance = target_.get();
    frame.gi.defines.clear(); // the lighting needs the switches, not the sampler's constants
    for (const auto& [name, value] : profile::shaderDefines(profile_))
        frame.gi.defines[name] = value;
    frame.gi.defines["GI_ENABLED"] = "";
}

} // namespace pb::render
