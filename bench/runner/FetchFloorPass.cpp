#include "FetchFloorPass.h"

#include "core/Error.h"
#include "passes/GiApplyPass.h"

namespace pb::bench {

FetchFloorPass::FetchFloorPass(const profile::Profile& profile) : profile_(profile) {}
FetchFloorPass::~FetchFloorPass() = default;

void FetchFloorPass::execute(render::FrameRenderer& renderer, const render::RenderView& view) {
    const render::FrameTargets* targets = renderer.targets();
    const render::GpuProbes* probes = renderer.gpuProbes();
    if (!targets || !probes || probes->volumes().empty())
        throw Error("fetch floor: needs a rendered frame with probes");
    const int div = profile::resolutionDivisor(profile_.gi.resolution);
    const render::GBuffer& gb = targets->gbuffer;
    const int w = std::max(1, gb.width() / div), h = std::max(1, gb.height() / div);
    if (!target_ || target_->desc().width != w || target_->desc().height != h) {
        fbo_.reset();
        target_ = std::make_unique<gl::Texture>(
            gl::nearestTexture(render::giTargetFormat(profile_.gi.targetFormat), w, h));
        fbo_ = std::make_unique<gl::Framebuffer>(
            "gi fetch floor", std::vector<const gl::Texture*>{target_.get()}, nullptr);
    }
    fbo_->bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    const gl::Program& prog = renderer.programs().get("fullscreen.vert", "bench_fetch_floor.frag",
                                                      render::ddgiConstantDefines());
    prog.use();
    gb.bindForReading(prog, 0);
    prog.set("u_giDivisor", div);
    prog.set("u_targetInvSize", glm::vec2(1.0f / float(w), 1.0f / float(h)));
    const int first = render::GiApplyPass::kFirstProbeUnit;
    probes->bindVolume(prog, probes->drawOrder().front(), first, view.eye);
    render::drawFullscreenTriangle(*targets);
    for (int u = first + render::GpuProbes::kUnitsPerVolume - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
}

} // namespace pb::bench
