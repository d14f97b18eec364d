#include "passes/CompositePass.h"

namespace pb::render {

void CompositePass::execute(FrameContext& frame) {
    frame.targets.outputFbo.bind();
    const gl::Program& prog = frame.programs.get("fullscreen.vert", "composite_tonemap.frag");
    prog.use();
    frame.targets.radiance.bind(0);
    prog.set("u_radiance", 0);
    prog.set("u_exposure", frame.settings.exposure / frame.preExposure); // exact: a power of 2
    drawFullscreenTriangle(frame.targets);
    glBindTexture(GL_TEXTURE_2D, 0);
}

} // namespace pb::render
