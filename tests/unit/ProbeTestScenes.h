#pragma once
// Scenes built directly in code for the probe/bake tests (no loader involved).
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace pb::test {

// Two triangles of the quad corner, corner+u, corner+u+v, corner+v whose front faces `front`.
inline void addQuad(scene::Primitive& p, glm::vec3 c, glm::vec3 u, glm::vec3 v, glm::vec3 front) {
    auto base = std::uint32_t(p.positions.size());
    for (glm::vec3 q : {c, c + u, c + u + v, c + v}) {
        p.positions.push_back(q);
        p.normals.push_back(glm::normalize(front));
        p.localBounds.extend(q);
    }
    bool ccw = glm::dot(glm::cross(u, v), front) > 0.0f;
    std::uint32_t a = base, b = base + 1, cc = base + 2, d = base + 3;
    if (ccw)
        p.indices.insert(p.indices.end(), {a, b, cc, a, cc, d});
    else
        p.indices.insert(p.indices.end(), {a, cc, b, a, d, cc});
}

// Axis-aligned box [lo, hi] as one primitive; faces point inwards (a room) or outwards (a
// solid block).
inline scene::Primitive boxPrimitive(glm::vec3 lo, glm::vec3 hi, bool inward, int material) {
    scene::Primitive p;
    p.material = material;
    glm::vec3 s = hi - lo;
    float sign = inward ? 1.0f : -1.0f;
    addQuad(p, lo, {s.x, 0, 0}, {0, 0, s.z}, {0, sign, 0});                  // floor
    addQuad(p, {lo.x, hi.y, lo.z}, {s.x, 0, 0}, {0, 0, s.z}, {0, -sign, 0}); // ceiling
    addQuad(p, lo, {0, s.y, 0}, {0, 0, s.z}, {sign, 0, 0});                  // -x wall
    addQuad(p, {hi.x, lo.y, lo.z}, {0, s.y, 0}, {0, 0, s.z}, {-sign, 0, 0}); // +x wall
    addQuad(p, lo, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, sign});                  // -z wall
    addQuad(p, {lo.x, lo.y, hi.z}, {s.x, 0, 0}, {0, s.y, 0}, {0, 0, -sign}); // +z wall
    return p;
}

inline scene::Scene emptyScene(glm::vec3 sky = glm::vec3(1.0f)) {
    scene::Scene s;
    s.name = "test-empty";
    s.materials.push_back(scene::Material{});
    s.sun.enabled = false;
    s.sky.radiance = sky;
    return s;
}

inline int addMaterial(scene::Scene& s, glm::vec3 albedo, glm::vec3 emissive = glm::vec3(0.0f),
                       bool doubleSided = false) {
    scene::Material m;
    m.baseColor = glm::vec4(albedo, 1.0f);
    m.emissive = emissive;
    m.doubleSided = doubleSided;
    s.materials.push_back(m);
    return int(s.materials.size()) - 1;
}

inline void addInstance(scene::Scene& s, scene::Primitive p, const glm::mat4& xf = glm::mat4(1.0f),
                        bool dynamic = false) {
    s.primitives.push_back(std::move(p));
    scene::Instance i;
    i.primitive = int(s.primitives.size()) - 1;
    i.transform = xf;
    i.dynamic = dynamic;
    s.instances.push_back(i);
}

// A closed room [-1,1]^3 whose walls all emit `le` and reflect `albedo` (sun off, sky black).
inline scene::Scene emissiveRoom(float le, float albedo) {
    scene::Scene s = emptyScene(glm::vec3(0.0f));
    int m = addMaterial(s, glm::vec3(albedo), glm::vec3(le));
    addInstance(s, boxPrimitive(glm::vec3(-1.0f), glm::vec3(1.0f), true, m));
    return s;
}

// A sunlit grey slab, top at y = 0, under a blue sky; sky and sun scaled by `lightScale`.
inline scene::Scene sunlitFloor(float lightScale = 1.0f) {
    scene::Scene s = emptyScene(glm::vec3(0.5f, 0.7f, 1.0f) * lightScale);
    s.sun.enabled = true;
    s.sun.intensity *= lightScale;
    int m = addMaterial(s, glm::vec3(0.6f));
    addInstance(s, boxPrimitive({-3, -0.5f, -3}, {3, 0, 3}, false, m));
    return s;
}

} // namespace pb::test
