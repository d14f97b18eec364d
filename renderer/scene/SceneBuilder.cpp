#include "scene/SceneBuilder.h"

#include "scene/MeshOps.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pb::scene {

int SceneBuilder::material(const std::string& name, const glm::vec3& albedo,
                           const glm::vec3& emissive) {
    Material m;
    m.name = name;
    m.baseColor = glm::vec4(albedo, 1.0f);
    m.emissive = emissive;
    scene_.materials.push_back(m);
    return int(scene_.materials.size()) - 1;
}

void SceneBuilder::box(const std::string& name, const glm::vec3& min, const glm::vec3& max,
                       int material, float yawDegrees, bool dynamic) {
    const glm::vec3 h = (max - min) * 0.5f;
    Primitive p;
    p.material = material;
    // Each face: outward normal n and two in-plane axes u, v with cross(u, v) = n, so the
    // corners c - u - v, c + u - v, c + u + v, c - u + v run counter-clockwise seen from outside.
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 n = axes[a] * sign;
            const glm::vec3 u = axes[(a + 1) % 3] * sign;
            const glm::vec3 v = axes[(a + 2) % 3];
            const glm::vec3 c = n * h, du = u * h, dv = v * h;
            const float su = glm::length(du) * 2.0f, sv = glm::length(dv) * 2.0f;
            const auto base = std::uint32_t(p.positions.size());
            const glm::vec3 corners[4] = {c - du - dv, c + du - dv, c + du + dv, c - du + dv};
            const glm::vec2 uvs[4] = {{0, 0}, {su, 0}, {su, sv}, {0, sv}};
            for (int k = 0; k < 4; ++k) {
                p.positions.push_back(corners[k]);
                p.normals.push_back(n);
                p.uvs.push_back(uvs[k]);
            }
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
                p.indices.push_back(base + i);
        }
    }
    p.localBounds = computeBounds(p.positions);

    glm::mat4 t = glm::translate(glm::mat4(1.0f), (min + max) * 0.5f);
    if (yawDegrees != 0.0f) t = glm::rotate(t, glm::radians(yawDegrees), glm::vec3(0, 1, 0));
    scene_.instances.push_back(Instance{name, int(scene_.primitives.size()), t, dynamic});
    scene_.primitives.push_back(std::move(p));
}

View& SceneBuilder::view(const std::string& name, const glm::vec3& position,
                         const glm::vec3& target, float fovYDegrees) {
    scene_.views.push_back(View{name, position, target, fovYDegrees});
    return scene_.views.back();
}

} // namespace pb::scene
