#pragma once
// The triangles the bake traces (static instances, visible materials), in world space: what
// automatic placement voxelises and where the placement benchmark picks surface points.
// Same selection and face normals as RayScene (counter-clockwise front, flipped for
// mirroring instance transforms).
#include "scene/Scene.h"

#include <vector>

namespace pb::raytrace {

struct WorldTriangle {
    glm::vec3 a, b, c;
    glm::vec3 normal; // unit, front side
    bool doubleSided = false;
    float area() const { return 0.5f * glm::length(glm::cross(b - a, c - a)); }
};

// Whether the bake traces this instance: static, with a valid primitive and a visible material.
// The one rule for "what the bake sees": RayScene (bake/) builds its BVH from it, placement
// voxelises it.
bool bakesInstance(const scene::Scene& scene, const scene::Instance& inst);

// Degenerate triangles (zero area, bad indices) are left out.
std::vector<WorldTriangle> staticBakeTriangles(const scene::Scene& scene);

} // namespace pb::raytrace
