#include "passes/ShadowPass.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pb::render {

void ShadowPass::execute(FrameContext& frame) {
    const scene::Scene& s = frame.scene.scene();
    frame.shadow = {};
    scene::Bounds bounds = s.worldBounds();
    if (!s.sun.enabled || bounds.empty()) return;

    int size = frame.settings.shadowMapSize;
    if (!map_ || map_->desc().width != size) {
        gl::TextureDesc d;
        d.format = gl::TextureFormat::Depth32F;
        d.width = d.height = size;
        d.filter = gl::Filter::Linear;
        d.depthCompare = true;
        map_ = std::make_unique<gl::Texture>(d);
        map_->label("shadow map");
        fbo_ = std::make_unique<gl::Framebuffer>("shadow", std::vector<const gl::Texture*>{},
                                                 map_.get());
    }

    // Light space centred on the bounds (double precision: offsets may be ~1e6 units).
    glm::dvec3 centre = glm::dvec3(bounds.center());
    double radius = std::max(0.5 * glm::length(glm::dvec3(bounds.size())), 1e-3);
    glm::dvec3 toSun = glm::normalize(glm::dvec3(s.sun.toSun));
    glm::dvec3 up = std::abs(toSun.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    glm::dmat4 lightView = glm::lookAt(toSun * radius, glm::dvec3(0.0), up);
    glm::dmat4 lightProj = glm::ortho(-radius, radius, -radius, radius, 0.0, 2.0 * radius);
    glm::dmat4 lightFromCentreRel = lightProj * lightView;

    fbo_->bind();
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // winding is unreliable in real scenes; offset handles acne
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    const gl::Program& prog = frame.programs.get("shadow_depth.vert", "shadow_depth.frag");
    prog.use();
    for (const scene::Instance& inst : s.instances) {
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        if (s.materials[size_t(prim.material)].invisible()) continue;
        glm::dmat4 model(inst.transform);
        model[3] -= glm::dvec4(centre, 0.0);
        prog.set("u_lightFromLocal", glm::mat4(lightFromCentreRel * model));
        const GpuPrimitive& g = frame.scene.primitive(inst.primitive);
        glBindVertexArray(g.vao.id());
        glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);

    glm::dmat4 bias = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) *
                      glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    glm::dmat4 centreRelFromRel = glm::translate(glm::dmat4(1.0), frame.view.eye - centre);
    frame.shadow.enabled = true;
    frame.shadow.map = map_.get();
    frame.shadow.shadowFromRel = glm::mat4(bias * lightFromCentreRel * centreRelFromRel);
    frame.shadow.texel = glm::vec2(1.0f / float(size));
    frame.shadow.normalOffset = float(1.5 * 2.0 * radius / size);
}

} // namespace pb::render
