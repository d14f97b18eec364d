#pragma once
// A brute-force CPU ray caster over a Scene's world triangles, for tests that ask geometric
// questions (is the box closed, does the sun reach this point, what does a view look at)
// without Embree or GL. Fine for test-sized ray counts, O(triangles) per ray.
#include "scene/Scene.h"

#include <cmath>
#include <limits>
#include <vector>

namespace pb::test {

class SceneRaycaster {
public:
    explicit SceneRaycaster(const scene::Scene& s) {
        for (const scene::Instance& inst : s.instances) {
            const scene::Primitive& p = s.primitives[size_t(inst.primitive)];
            if (s.materials[size_t(p.material)].invisible()) continue; // as the bake does
            for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
                Tri t;
                for (int k = 0; k < 3; ++k)
                    t.v[k] = glm::dvec3(scene::worldPosition(s, inst, p.indices[i + size_t(k)]));
                tris_.push_back(t);
            }
        }
    }

    // Distance to the nearest hit along the ray (both faces count), or infinity.
    double cast(const glm::vec3& origin, const glm::vec3& direction) const {
        const glm::dvec3 o(origin), d = glm::normalize(glm::dvec3(direction));
        double best = std::numeric_limits<double>::infinity();
        for (const Tri& t : tris_) { // Moller-Trumbore, in double so edges do not leak
            const glm::dvec3 e1 = t.v[1] - t.v[0], e2 = t.v[2] - t.v[0];
            const glm::dvec3 pv = glm::cross(d, e2);
            const double det = glm::dot(e1, pv);
            if (std::abs(det) < 1e-18) continue;
            const double inv = 1.0 / det;
            const glm::dvec3 tv = o - t.v[0];
            const double u = glm::dot(tv, pv) * inv;
            if (u < -1e-9 || u > 1.0 + 1e-9) continue;
            const glm::dvec3 qv = glm::cross(tv, e1);
            const double v = glm::dot(d, qv) * inv;
            if (v < -1e-9 || u + v > 1.0 + 1e-9) continue;
            const double dist = glm::dot(e2, qv) * inv;
            if (dist > 1e-7 && dist < best) best = dist;
        }
        return best;
    }

    bool hits(const glm::vec3& origin, const glm::vec3& direction) const {
        return std::isfinite(cast(origin, direction));
    }

    size_t triangleCount() const { return tris_.size(); }

private:
    struct Tri {
        glm::dvec3 v[3];
    };
    std::vector<Tri> tris_;
};

// `n` directions spread evenly over the sphere (Fibonacci lattice).
inline std::vector<glm::vec3> sphereDirections(int n) {
    std::vector<glm::vec3> dirs;
    const double golden = 3.14159265358979 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - y * y);
        dirs.emplace_back(float(r * std::cos(golden * i)), float(y),
                          float(r * std::sin(golden * i)));
    }
    return dirs;
}

} // namespace pb::test
