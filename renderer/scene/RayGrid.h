#pragma once
// A small CPU ray caster over a scene's static, visible triangles (uniform grid, built in
// milliseconds). It lets the scene module ask "what does this camera see?" without Embree,
// which only the bake links: the default view uses it to keep out of walls and furniture.
#include "scene/Scene.h"

#include <cstdint>
#include <vector>

namespace pb::scene {

struct RayHit {
    float distance;  // infinity when nothing is hit
    bool backFacing; // a single-sided surface seen from behind (its normals point away)
    glm::vec3 normal{0.0f}; // unit geometric normal, on the side the ray came from
    bool emissive = false;  // the hit surface's material emits light
};

class RayGrid {
public:
    explicit RayGrid(const Scene& scene);

    bool empty() const { return tris_.empty(); }
    // Centroids of the emissive triangles (sampled by what sees light: DefaultView).
    const std::vector<glm::vec3>& emitterCentroids() const { return emitters_; }
    // Nearest hit along origin + t * direction (direction unit length) for t in (0, maxDistance].
    RayHit cast(const glm::vec3& origin, const glm::vec3& direction, float maxDistance) const;
    // The box the grid covers: the triangles' bounds, every side at least 1e-3 of the
    // diagonal (empty without triangles).
    const Bounds& bounds() const { return bounds_; }

private:
    struct Tri {
        glm::vec3 v0, e1, e2;
        glm::vec3 facing; // geometric normal agreeing with the vertex normals; 0: double-sided
        bool emissive = false;
    };
    void build();
    size_t cellIndex(const glm::ivec3& cell) const;

    std::vector<Tri> tris_;
    std::vector<glm::vec3> emitters_;
    Bounds bounds_;
    glm::ivec3 dims_{1};
    glm::vec3 cellSize_{1.0f};
    std::vector<std::uint32_t> cellStart_; // CSR: cell c holds cellTris_[cellStart_[c], [c+1])
    std::vector<std::uint32_t> cellTris_;
};

} // namespace pb::scene
