#include "frame/DepthReadback.h"

#include "frame/Readback.h"

namespace pb::render {

image::ImageF readDepthDistance(const FrameTargets& t, const RenderView& view,
                                gl::ProgramCache& programs) {
    gl::Texture distance =
        gl::nearestTexture(gl::TextureFormat::RGBA32F, t.gbuffer.width(), t.gbuffer.height());
    gl::Framebuffer fbo("depth-readback", {&distance}, nullptr);
    fbo.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    const gl::Program& prog = programs.get("fullscreen.vert", "debug_depth_copy.frag");
    prog.use();
    t.gbuffer.depth().bind(0);
    prog.set("u_depth", 0);
    prog.set("u_relFromClip", view.relFromClip);
    drawFullscreenTriangle(t);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return readFloat(distance);
}

} // namespace pb::render
