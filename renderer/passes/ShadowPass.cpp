#include "passes/ShadowPass.h"

#include "scene/RayGrid.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pb::render {

namespace {

// Depth bias, in the lighting shader rather than glPolygonOffset: glPolygonOffset's slope
// term follows the *caster's* slope without bound, and a thin wall seen edge-on by the sun
// was pushed behind the floor it shadows. The shader's term follows the receiver's angle to
// the sun and is clamped (lighting_direct.frag, sunShadow).
// 1 texel, plus 1.5 texels per unit of tan(angle to the sun) up to tan = 3: chosen by a sweep
// on the courtyard golden (acne on its far wall below it) and ShadowSeamLeakTest (leaks above
// it), studies/results/2026-12-02-sun-shadow-view-fit.md.
constexpr glm::vec3 kDepthBias{1.0f, 1.5f, 3.0f};
constexpr double kNormalOffsetTexels = 1.5;

void drawDepth(const FrameContext& frame, const gl::Framebuffer& fbo, const glm::dmat4& clipFromCentreRel,
               const glm::dvec3& centre) {
    const scene::Scene& s = frame.scene.scene();
    fbo.bind();
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    const gl::Program& prog = frame.programs.get("shadow_depth.vert", "shadow_depth.frag");
    prog.use();
    for (const scene::Instance& inst : s.instances) {
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        if (s.materials[size_t(prim.material)].invisible()) continue;
        glm::dmat4 model(inst.transform);
        model[3] -= glm::dvec4(centre, 0.0);
        prog.set("u_lightFromLocal", glm::mat4(clipFromCentreRel * model));
        const GpuPrimitive& g = frame.scene.primitive(inst.primitive);
        glBindVertexArray(g.vao.id());
        glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
}

ShadowMapView mapView(const gl::Texture& depth, const glm::dmat4& clipFromCentreRel,
                      const glm::dmat4& centreRelFromRel, double squareSize, double depthRange) {
    const glm::dmat4 bias = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) *
                            glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    const int size = depth.desc().width;
    ShadowMapView m;
    m.map = &depth;
    m.fromRel = glm::mat4(bias * clipFromCentreRel * centreRelFromRel);
    m.texel = 1.0f / float(size);
    const double texelWorld = squareSize / double(size);
    m.normalOffset = float(kNormalOffsetTexels * texelWorld);
    m.depthTexel = float(texelWorld / depthRange);
    return m;
}

} // namespace

ShadowPass::ShadowPass() = default;
ShadowPass::~ShadowPass() = default;

void ShadowPass::ensure(Map& map, int size, const char* label) {
    if (map.depth && map.depth->desc().width == size) return;
    gl::TextureDesc d;
    d.format = gl::TextureFormat::Depth32F;
    d.width = d.height = size;
    d.filter = gl::Filter::Linear;
    d.depthCompare = true;
    map.depth = std::make_unique<gl::Texture>(d);
    map.depth->label(label);
    map.fbo = std::make_unique<gl::Framebuffer>(label, std::vector<const gl::Texture*>{},
                                                map.depth.get());
}

std::optional<LightSquare> ShadowPass::fitFor(const RenderView& view, const glm::dmat4& lightFromWorld,
                                              const LightSquare& sceneSquare) {
    const FitKey key{view.eye, view.relFromClip, view.farPlane, lightFromWorld};
    if (fitKey_ != key) {
        fit_ = fitShadowToView(*grid_, view, lightFromWorld, sceneSquare);
        fitKey_ = key;
    }
    return fit_;
}

void ShadowPass::execute(FrameContext& frame) {
    const scene::Scene& s = frame.scene.scene();
    frame.shadow = {};
    scene::Bounds bounds = s.worldBounds();
    if (!s.sun.enabled || bounds.empty()) return;
    if (!grid_ || gridScene_ != &s) {
        grid_ = std::make_unique<scene::RayGrid>(s);
        gridScene_ = &s;
        fitKey_.reset();
    }

    // Light space centred on the bounds (double precision: offsets may be ~1e6 units).
    const glm::dvec3 centre = glm::dvec3(bounds.center());
    const double radius = std::max(0.5 * glm::length(glm::dvec3(bounds.size())), 1e-3);
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(s.sun.toSun));
    const glm::dvec3 up = std::abs(toSun.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dmat4 lightView = glm::lookAt(toSun * radius, glm::dvec3(0.0), up);
    const LightSquare sceneSquare{glm::dvec2(-radius), 2.0 * radius};
    const glm::dmat4 lightFromWorld = lightView * glm::translate(glm::dmat4(1.0), -centre);
    const std::optional<LightSquare> fit = fitFor(frame.view, lightFromWorld, sceneSquare);
    const LightSquare viewSquare = fit.value_or(sceneSquare);

    auto ortho = [&](const LightSquare& q) {
        return glm::ortho(q.min.x, q.min.x + q.size, q.min.y, q.min.y + q.size, 0.0, 2.0 * radius) *
               lightView;
    };
    const int size = frame.settings.shadowMapSize;
    ensure(view_, size, "shadow map (view)");
    ensure(scene_, sceneShadowMapSize(size), "shadow map (scene)");

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // winding is unreliable in real scenes
    drawDepth(frame, *view_.fbo, ortho(viewSquare), centre);
    drawDepth(frame, *scene_.fbo, ortho(sceneSquare), centre);
    glDisable(GL_DEPTH_TEST);

    const glm::dmat4 centreRelFromRel = glm::translate(glm::dmat4(1.0), frame.view.eye - centre);
    frame.shadow.enabled = true;
    frame.shadow.bias = kDepthBias;
    frame.shadow.view = mapView(*view_.depth, ortho(viewSquare), centreRelFromRel, viewSquare.size, 2.0 * radius);
    frame.shadow.scene = mapView(*scene_.depth, ortho(sceneSquare), centreRelFromRel, sceneSquare.size, 2.0 * radius);
}

} // namespace pb::render
