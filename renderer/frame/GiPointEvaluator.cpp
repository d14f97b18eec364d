#include "frame/GiPointEvaluator.h"

#include "core/Error.h"
#include "frame/Readback.h"
#include "gl/Framebuffer.h"
#include "passes/GiApplyPass.h"

#include <algorithm>

namespace pb::render {

GiPointEvaluator::GiPointEvaluator(const GpuProbes& probes, const profile::Profile& profile,
                                   gl::ProgramCache& programs)
    : probes_(probes), profile_(profile), programs_(programs), vao_(gl::genVertexArray()) {}

std::vector<glm::vec4> GiPointEvaluator::evaluate(const std::vector<GiPoint>& points, int width) {
    if (points.empty()) return {};
    if (width < 1) throw Error("GiPointEvaluator: width must be >= 1");
    const int w = std::min<int>(width, int(points.size()));
    const int h = int((points.size() + size_t(w) - 1) / size_t(w));
    // Unused texels sit far outside every volume: discarded, they stay 0.
    std::vector<glm::vec4> pos(size_t(w) * size_t(h), glm::vec4(1e30f, 1e30f, 1e30f, 1.0f));
    std::vector<glm::vec4> nrm(pos.size(), glm::vec4(0, 1, 0, 0)), view = nrm;
    for (size_t i = 0; i < points.size(); ++i) {
        pos[i] = glm::vec4(points[i].position, 1.0f);
        nrm[i] = glm::vec4(points[i].normal, 0.0f);
        view[i] = glm::vec4(points[i].view, 0.0f);
    }
    gl::Texture posTex = gl::nearestTexture(gl::TextureFormat::RGBA32F, w, h);
    gl::Texture nrmTex = gl::nearestTexture(gl::TextureFormat::RGBA32F, w, h);
    gl::Texture viewTex = gl::nearestTexture(gl::TextureFormat::RGBA32F, w, h);
    posTex.upload(pos.data());
    nrmTex.upload(nrm.data());
    viewTex.upload(view.data());
    gl::Texture target = gl::nearestTexture(giTargetFormat(profile_.gi.targetFormat), w, h);
    gl::Framebuffer fbo("gi points", {&target}, nullptr);

    fbo.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    const gl::Program& prog = programs_.get("fullscreen.vert", probes_.technique().pointsShader(),
                                            giShaderDefines(profile_, &probes_));
    prog.use();
    posTex.bind(0);
    nrmTex.bind(1);
    viewTex.bind(2);
    prog.set("u_pointPosition", 0);
    prog.set("u_pointNormal", 1);
    prog.set("u_pointView", 2);
    glBindVertexArray(vao_.id());
    for (int v : probes_.drawOrder()) {
        probes_.bindVolume(prog, v, 3, glm::dvec3(0.0)); // world space
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindVertexArray(0);
    probes_.unbindTextures(3 + probes_.unitsPerVolume()); // the points and the probes
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    image::ImageF img = readFloat(target); // rows top to bottom: GL row y is h - 1 - y
    std::vector<glm::vec4> out(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        size_t x = i % size_t(w), y = size_t(h) - 1 - i / size_t(w);
        const float* px = &img.pixels[(y * size_t(w) + x) * 4];
        out[i] = glm::vec4(px[0], px[1], px[2], px[3]);
    }
    return out;
}

} // namespace pb::render
