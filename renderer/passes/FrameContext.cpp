#include "passes/FrameContext.h"

#include <cmath>

namespace pb::render {

namespace {
gl::Texture makeColour(gl::TextureFormat f, int w, int h) {
    gl::TextureDesc d;
    d.format = f;
    d.width = w;
    d.height = h;
    d.filter = gl::Filter::Nearest;
    return gl::Texture(d);
}
} // namespace

FrameTargets::FrameTargets(int width, int height)
    : gbuffer(width, height), radiance(makeColour(gl::TextureFormat::RGBA16F, width, height)),
      radianceFbo("radiance", {&radiance}, nullptr),
      output(makeColour(gl::TextureFormat::RGBA8, width, height)),
      outputFbo("output", {&output}, nullptr), emptyVao(gl::genVertexArray()) {}

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
