#include "passes/DirectLightingPass.h"

#include <cmath>
#include <string>

namespace pb::render {

namespace {
std::string at(const char* name, int i) {
    return std::string(name) + "[" + std::to_string(i) + "]";
}

void setLights(const gl::Program& prog, const scene::Scene& s, const RenderView& view) {
    int count = std::min<int>(int(s.lights.size()), DirectLightingPass::kMaxLights);
    prog.set("u_lightCount", count);
    for (int i = 0; i < count; ++i) {
        const scene::Light& l = s.lights[size_t(i)];
        float type = l.type == scene::LightType::Directional ? 0.0f
                     : l.type == scene::LightType::Point     ? 1.0f
                                                             : 2.0f;
        prog.set(at("u_lightPosType", i), glm::vec4(view.toRel(l.position), type));
        prog.set(at("u_lightDirRange", i), glm::vec4(glm::normalize(l.direction), l.range));
        prog.set(at("u_lightColor", i), glm::vec4(l.color * l.intensity, 0.0f));
        prog.set(at("u_lightCone", i),
                 glm::vec4(std::cos(l.outerConeAngle), std::cos(l.innerConeAngle), 0, 0));
    }
}
} // namespace

void DirectLightingPass::execute(FrameContext& frame) {
    const scene::Scene& s = frame.scene.scene();
    frame.targets.radianceFbo.bind();
    // Without probes: the variant without defines (what the golden images were made with).
    gl::Defines defines = frame.gi.enabled ? frame.gi.defines : gl::Defines{};
    if (frame.settings.indirectOnly) defines["DEBUG_INDIRECT_ONLY"] = "";
    const gl::Program& prog =
        frame.programs.get("fullscreen.vert", "lighting_direct.frag", defines);
    prog.use();
    frame.targets.gbuffer.bindForReading(prog, 0);
    const int shadowUnit = gbufferDepthUnit(0) + 1, sceneShadowUnit = shadowUnit + 1;
    prog.set("u_shadowMap", shadowUnit);
    prog.set("u_shadowMapScene", sceneShadowUnit);
    prog.set("u_relFromClip", frame.view.relFromClip);
    prog.set("u_skyRadiance", s.sky.radiance);
    prog.set("u_ambientUp", frame.settings.ambientUp);
    prog.set("u_ambientDown", frame.settings.ambientDown);
    prog.set("u_preExposure", frame.preExposure);
    bool sun = frame.shadow.enabled;
    prog.set("u_sunEnabled", sun ? 1 : 0);
    prog.set("u_toSun", glm::normalize(s.sun.toSun));
    prog.set("u_sunIrradiance", s.sun.color * s.sun.intensity);
    if (sun) {
        const ShadowMapView& v = frame.shadow.view;
        const ShadowMapView& sc = frame.shadow.scene;
        v.map->bind(shadowUnit);
        sc.map->bind(sceneShadowUnit);
        prog.set("u_shadowFromRel", v.fromRel);
        prog.set("u_shadowTexel", v.texel);
        prog.set("u_shadowNormalOffset", v.normalOffset);
        prog.set("u_shadowDepthTexel", v.depthTexel);
        prog.set("u_shadowNormalToMap", v.normalToMap);
        prog.set("u_shadowSceneFromRel", sc.fromRel);
        prog.set("u_shadowSceneNormalOffset", sc.normalOffset);
        prog.set("u_shadowSceneDepthTexel", sc.depthTexel);
        prog.set("u_shadowBias", frame.shadow.bias);
    }
    const int giUnit = sceneShadowUnit + 1;
    if (frame.gi.enabled) {
        frame.gi.irradiance->bind(giUnit);
        prog.set("u_giIrradiance", giUnit);
    }
    const int shUnit = giUnit + 1;
    if (frame.gi.enabled && frame.gi.dynamicSh) {
        frame.gi.dynamicSh->bind(shUnit);
        prog.set("u_giDynamicSh", shUnit);
    }
    setLights(prog, s, frame.view);
    drawFullscreenTriangle(frame.targets);
    for (int u = 0; u <= shUnit; ++u) {
        glActiveTexture(GL_TEXTURE0 + u);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

} // namespace pb::render
