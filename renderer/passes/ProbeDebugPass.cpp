#include "passes/ProbeDebugPass.h"

#include "probes/ProbeSampler.h"

namespace pb::render {

ProbeDebugPass::ProbeDebugPass(const GpuProbes& probes, bool visibility)
    : probes_(probes), visibility_(visibility) {}

void ProbeDebugPass::execute(FrameContext& frame) {
    if (fboFor_ != &frame.targets) {
        fbo_ = std::make_unique<gl::Framebuffer>(
            "debug probes", std::vector<const gl::Texture*>{&frame.targets.radiance},
            &frame.targets.gbuffer.depth());
        fboFor_ = &frame.targets;
    }
    fbo_->bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    gl::Defines defines = ddgiConstantDefines();
    if (visibility_) defines["DEBUG_VISIBILITY"] = "";
    defines["GI_GUARD_EXPOSURE_ON"] = ""; // the radiance target is pre-exposed (FrameContext.h)
    const gl::Program& prog =
        frame.programs.get("debug_probe_sphere.vert", "debug_probe_sphere.frag", defines);
    prog.use();
    prog.set("u_clipFromRel", frame.view.clipFromRel);
    prog.set("u_visibilityScale", 0.5f * frame.preExposure / frame.settings.exposure);
    glBindVertexArray(frame.targets.emptyVao.id());
    for (size_t v = 0; v < probes_.volumes().size(); ++v) {
        const GpuProbeVolume& vol = probes_.volumes()[v];
        probes_.bindVolume(prog, int(v), 0, frame.view.eye, frame.preExposure);
        // An eighth of the smallest cell (biasDistance = kBiasScale x it): spheres never touch.
        prog.set("u_sphereRadius", 0.125f * vol.biasDistance / probes::kBiasScale);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6 * 12 * 6,
                              vol.counts.x * vol.counts.y * vol.counts.z);
    }
    glBindVertexArray(0);
    glDisable(GL_DEPTH_TEST);
    for (int u = GpuProbes::kUnitsPerVolume - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace pb::render
