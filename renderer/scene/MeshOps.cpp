#include "scene/MeshOps.h"

#include <cmath>

namespace pb::scene {

void generateSmoothNormals(Primitive& prim) {
    std::vector<glm::vec3>& n = prim.normals;
    n.assign(prim.positions.size(), glm::vec3(0.0f));
    const std::vector<glm::vec3>& p = prim.positions;
    const std::vector<std::uint32_t>& idx = prim.indices;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        const std::uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
        // Relative to `a` so that scenes far from the origin keep their precision.
        const glm::vec3 faceArea2 = glm::cross(p[b] - p[a], p[c] - p[a]);
        n[a] += faceArea2;
        n[b] += faceArea2;
        n[c] += faceArea2;
    }
    for (glm::vec3& v : n) {
        // Divide by the largest component first: sums of huge or tiny triangles would
        // overflow or underflow when squared.
        const float m = glm::max(glm::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z));
        if (m > 0.0f && std::isfinite(m)) {
            v /= m;
            v /= std::sqrt(glm::dot(v, v));
        } else {
            v = glm::vec3(0, 1, 0);
        }
    }
}

bool normalizeNormals(std::vector<glm::vec3>& normals) {
    for (glm::vec3& v : normals) {
        const float len2 = glm::dot(v, v);
        if (!(len2 > 1e-20f) || !std::isfinite(len2)) return false;
        v *= 1.0f / std::sqrt(len2);
    }
    return true;
}

Bounds computeBounds(const std::vector<glm::vec3>& positions) {
    Bounds b;
    for (const glm::vec3& p : positions)
        b.extend(p);
    return b;
}

} // namespace pb::scene
