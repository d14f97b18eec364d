#include "raytrace/StaticTriangles.h"

namespace pb::raytrace {

bool bakesInstance(const scene::Scene& s, const scene::Instance& inst) {
    if (inst.dynamic || inst.primitive < 0 || inst.primitive >= int(s.primitives.size()))
        return false;
    const int m = s.primitives[size_t(inst.primitive)].material;
    return m < 0 || m >= int(s.materials.size()) || !s.materials[size_t(m)].invisible();
}

std::vector<WorldTriangle> staticBakeTriangles(const scene::Scene& s) {
    std::vector<WorldTriangle> out;
    for (const scene::Instance& inst : s.instances) {
        if (!bakesInstance(s, inst)) continue;
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        const std::size_t nv = prim.positions.size();
        const bool mirrored = glm::determinant(glm::mat3(inst.transform)) < 0.0f;
        const int m = prim.material;
        const bool doubleSided = m >= 0 && m < int(s.materials.size()) && s.materials[size_t(m)].doubleSided;
        for (std::size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
            std::uint32_t i[3] = {prim.indices[t], prim.indices[t + 1], prim.indices[t + 2]};
            if (i[0] >= nv || i[1] >= nv || i[2] >= nv) continue;
            WorldTriangle w;
            w.a = glm::vec3(inst.transform * glm::vec4(prim.positions[i[0]], 1.0f));
            w.b = glm::vec3(inst.transform * glm::vec4(prim.positions[i[1]], 1.0f));
            w.c = glm::vec3(inst.transform * glm::vec4(prim.positions[i[2]], 1.0f));
            glm::vec3 n = glm::cross(w.b - w.a, w.c - w.a);
            float len = glm::length(n);
            if (!(len > 0.0f)) continue;
            w.normal = (mirrored ? -n : n) / len;
            w.doubleSided = doubleSided;
            out.push_back(w);
        }
    }
    return out;
}

} // namespace pb::raytrace
