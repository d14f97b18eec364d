#include "passes/GBufferPass.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace pb::render {

void GBufferPass::execute(FrameContext& frame) {
    const scene::Scene& s = frame.scene.scene();
    if (objectsOf_ != &s) {
        dynamic_ = findDynamicObjects(s);
        objectsOf_ = &s;
    }
    const GBuffer& gb = frame.targets.gbuffer;
    gb.framebuffer().bind();
    glClearColor(0, 0, 0, 0);
    glClearDepthf(1.0f);
    glClearStencil(0); // kept 0 all frame: GiApplyPass copies it as its cleared stencil
    glStencilMask(0xFFu);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);

    const gl::Program& prog = frame.programs.get("gbuffer_geometry.vert", "gbuffer_geometry.frag",
                                                 gbufferOutputDefines());
    prog.use();
    prog.set("u_clipFromRel", frame.view.clipFromRel);
    prog.set("u_baseColorTex", 0);
    prog.set("u_emissiveTex", 1);

    for (size_t i = 0; i < s.instances.size(); ++i) {
        const scene::Instance& inst = s.instances[i];
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        const scene::Material& m = s.materials[size_t(prim.material)];
        if (m.invisible() || prim.indices.empty()) continue;
        if (m.doubleSided)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        prog.set("u_relFromLocal", frame.view.relFromLocal(inst.transform));
        prog.set("u_normalFromLocal", glm::mat3(glm::inverseTranspose(inst.transform)));
        prog.set("u_baseColor", m.baseColor);
        // Pre-exposed (gi.guard_exposure) so a bright emitter fits the RGBA16F channel.
        prog.set("u_emissive", m.emissive * frame.preExposure);
        prog.set("u_doubleSided", m.doubleSided ? 1 : 0);
        // Deferred shading has no transparency: BLEND is drawn alpha-tested at 0.5.
        float cutoff = m.alphaMode == scene::AlphaMode::Mask    ? m.alphaCutoff
                       : m.alphaMode == scene::AlphaMode::Blend ? 0.5f
                                                                : -1.0f;
        prog.set("u_alphaCutoff", cutoff);
        prog.set("u_flags", float(gbufferFlagBits(dynamic_, int(i))) / 255.0f);
        bool hasBase = m.baseColorTexture >= 0 && size_t(m.baseColorTexture) < s.textures.size();
        bool hasEmissive = m.emissiveTexture >= 0 && size_t(m.emissiveTexture) < s.textures.size();
        prog.set("u_hasBaseColorTex", hasBase ? 1 : 0);
        prog.set("u_hasEmissiveTex", hasEmissive ? 1 : 0);
        if (hasBase) frame.scene.texture(m.baseColorTexture).bind(0);
        if (hasEmissive) frame.scene.texture(m.emissiveTexture).bind(1);
        const GpuPrimitive& g = frame.scene.primitive(inst.primitive);
        glBindVertexArray(g.vao.id());
        glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    for (int unit : {0, 1}) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
}

} // namespace pb::render
