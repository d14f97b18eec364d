#include "passes/DynamicShPass.h"

#include "core/Error.h"
#include "passes/GiApplyPass.h"
#include "probes/bake/RayDirections.h"

namespace pb::render {

namespace {

gl::Texture floatTexture(int w, int h) {
    return gl::nearestTexture(gl::TextureFormat::RGBA32F, w, h);
}

int checkedRows(const DynamicObjects& objects) {
    if (objects.objects.size() > size_t(kMaxShObjects))
        throw Error("gi.dynamic=sh: the scene has " + std::to_string(objects.objects.size()) +
                    " dynamic objects; the GBuffer flags number at most " +
                    std::to_string(kMaxShObjects));
    return std::max<int>(1, int(objects.objects.size()));
}

} // namespace

std::vector<glm::vec4> shFitWeights(const std::vector<glm::vec3>& directions) {
    // Normal equations of the fit f(d) ~ c0 + c1 d.x + c2 d.y + c3 d.z: G c = Y^T f.
    glm::dmat4 gram(0.0);
    auto basis = [](const glm::vec3& d) { return glm::dvec4(1.0, d.x, d.y, d.z); };
    for (const glm::vec3& d : directions)
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                gram[c][r] += basis(d)[r] * basis(d)[c];
    const glm::dmat4 inv = glm::inverse(gram);
    std::vector<glm::vec4> w;
    for (const glm::vec3& d : directions)
        w.push_back(glm::vec4(inv * basis(d)));
    return w;
}

DynamicShPass::DynamicShPass(const GpuProbes& probes, const profile::Profile& profile,
                             const scene::Scene& scene)
    : probes_(probes), defines_(giShaderDefines(profile, &probes)), objects_(findDynamicObjects(scene)),
      rows_(checkedRows(objects_)), directions_(floatTexture(kDirections, rows_)),
      positions_(floatTexture(kDirections, rows_)), weights_(floatTexture(kDirections, 1)),
      lookups_(floatTexture(kDirections, rows_)), coefficients_(floatTexture(4, rows_)),
      lookupFbo_("dynamic sh lookups", {&lookups_}, nullptr),
      coefficientFbo_("dynamic sh coefficients", {&coefficients_}, nullptr) {
    const std::vector<glm::vec3> dirs = probes::sphericalFibonacci(kDirections);
    std::vector<glm::vec4> texels;
    for (int r = 0; r < rows_; ++r)
        for (const glm::vec3& d : dirs)
            texels.push_back(glm::vec4(d, 0.0f));
    directions_.upload(texels.data());
    weights_.upload(shFitWeights(dirs).data());
}

std::size_t DynamicShPass::bytes() const {
    return directions_.bytes() + positions_.bytes() + weights_.bytes() + lookups_.bytes() +
           coefficients_.bytes();
}

void DynamicShPass::execute(FrameContext& frame) {
    frame.gi.dynamicSh = &coefficients_;
    if (objects_.objects.empty()) return; // no dynamic pixel will read it
    // The centres relative to this frame's eye (double on the CPU, like every position).
    std::vector<glm::vec4> centres;
    for (int r = 0; r < rows_; ++r) {
        const glm::vec3 c(objects_.objects[size_t(r)].centre() - frame.view.eye);
        centres.insert(centres.end(), size_t(kDirections), glm::vec4(c, 1.0f));
    }
    positions_.upload(centres.data());

    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    lookupFbo_.bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    const gl::Program& eval =
        frame.programs.get("fullscreen.vert", probes_.technique().pointsShader(), defines_);
    eval.use();
    positions_.bind(0);
    directions_.bind(1);
    eval.set("u_pointPosition", 0);
    eval.set("u_pointNormal", 1);
    eval.set("u_pointView", 1);
    for (int v : probes_.drawOrder()) { // largest first, overwriting: the smallest one wins
        probes_.bindVolume(eval, v, 2, frame.view.eye, frame.preExposure);
        // An object's centre is no surface: every probe counts, whichever way the direction
        // looked up points (no behind-surface fade, ProbeSampler.h kBehindRampCells; with it a
        // sparse bake left directions with all 8 probes behind unlit).
        eval.set("u_ddgiBehindInvWidth", 0.0f);
        drawFullscreenTriangle(frame.targets);
    }

    coefficientFbo_.bind();
    const gl::Program& fit =
        frame.programs.get("fullscreen.vert", "gi_dynamic_sh_project.frag", {});
    fit.use();
    lookups_.bind(0);
    weights_.bind(1);
    fit.set("u_shLookups", 0);
    fit.set("u_shWeights", 1);
    fit.set("u_shDirections", kDirections);
    drawFullscreenTriangle(frame.targets);
    probes_.unbindTextures(2 + probes_.unitsPerVolume()); // the fit's inputs and the probes
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace pb::render
