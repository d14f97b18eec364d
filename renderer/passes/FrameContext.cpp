#include "passes/FrameContext.h"

#include <cmath>

namespace pb::render {

FrameTargets::FrameTargets(int width, int height)
    : gbuffer(width, height),
      radiance(gl::nearestTexture(gl::TextureFormat::RGBA16F, width, height)),
      radianceFbo("radiance", {&radiance}, nullptr),
      output(gl::nearestTexture(gl::TextureFormat::RGBA8, width, height)),
      outputFbo("output", {&output}, nullptr), emptyVao(gl::genVertexArray()) {
    radiance.label("radiance");
    output.label("output");
}

float preExposureScale(float exposure) {
    if (!(exposure > 0.0f) || !std::isfinite(exposure)) return 1.0f;
    return std::ldexp(1.0f, int(std::trunc(std::log2(exposure))));
}

void drawFullscreenTriangle(const FrameTargets& targets) {
    glBindVertexArray(targets.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

} // namespace pb::render
