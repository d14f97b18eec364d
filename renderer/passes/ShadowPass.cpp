#include "passes/ShadowPass.h"

#include "scene/RayGrid.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace pb::render {

namespace {

// Depth bias, mostly on the casters (shadow_depth.vert), in texels of the map drawn: each caster
// moves into its back side, by x texels plus y per unit of tan(angle to the sun), tan capped
// at z. The side the sun lights is pushed away from the sun: it is also a receiver and must not
// shadow itself. The side facing away from the sun is pulled towards it: the lighting never
// lights it, it only occludes, and pulled it still covers the floor at a wall's foot and the
// corner of a room of single faces (issue 42's box, ShadowZeroThickness) where a receiver-side
// bias let the sun through. The pull stays under what the receiver keeps (kReceiverBias and
// half a texel of normal offset): a convex edge's unlit face, right behind its sunlit face,
// then never pokes through it. glPolygonOffset cannot do this: its slope term follows the
// caster without bound and pushes a wall seen edge-on behind the floor it shadows.
// Chosen by ShadowZeroThickness, ShadowSeamLeakTest, TruthDirect and the courtyard golden:
// studies/results/2026-12-03-caster-side-shadow-bias.md.
constexpr glm::vec3 kLitSideBias{1.0f, 1.5f, 6.0f};
constexpr glm::vec3 kUnlitSideBias{0.5f, 0.5f, 3.0f};
// What the receiver keeps: x a constant, in texels; y the steepest receiver plane (texels of
// depth per texel) its PCF taps follow (lighting_direct.frag, sunShadow).
constexpr glm::vec2 kReceiverBias{0.5f, 3.0f};
constexpr double kNormalOffsetTexels = 0.5;

void drawDepth(const FrameContext& frame, const gl::Framebuffer& fbo, const glm::dmat4& clipFromCentreRel,
               const glm::dvec3& centre, double depthTexel) {
    const scene::Scene& s = frame.scene.scene();
    fbo.bind();
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    const gl::Program& prog = frame.programs.get("shadow_depth.vert", "shadow_depth.frag");
    prog.use();
    prog.set("u_toSun", glm::normalize(s.sun.toSun));
    prog.set("u_depthTexel", float(2.0 * depthTexel)); // clip z spans 2
    prog.set("u_litSideBias", kLitSideBias);
    prog.set("u_unlitSideBias", kUnlitSideBias);
    for (const scene::Instance& inst : s.instances) {
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        const scene::Material& mat = s.materials[size_t(prim.material)];
        if (mat.invisible()) continue;
        prog.set("u_doubleSided", mat.doubleSided ? 1 : 0);
        prog.set("u_normalFromLocal", glm::mat3(glm::inverseTranspose(inst.transform)));
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
    m.normalToMap = glm::mat3(glm::inverseTranspose(glm::dmat3(m.fromRel)));
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
    drawDepth(frame, *view_.fbo, ortho(viewSquare), centre,
              viewSquare.size / double(size) / (2.0 * radius));
    drawDepth(frame, *scene_.fbo, ortho(sceneSquare), centre,
              sceneSquare.size / double(sceneShadowMapSize(size)) / (2.0 * radius));
    glDisable(GL_DEPTH_TEST);

    const glm::dmat4 centreRelFromRel = glm::translate(glm::dmat4(1.0), frame.view.eye - centre);
    frame.shadow.enabled = true;
    frame.shadow.bias = kReceiverBias;
    frame.shadow.view = mapView(*view_.depth, ortho(viewSquare), centreRelFromRel, viewSquare.size, 2.0 * radius);
    frame.shadow.scene = mapView(*scene_.depth, ortho(sceneSquare), centreRelFromRel, sceneSquare.size, 2.0 * radius);
}

} // namespace pb::render
