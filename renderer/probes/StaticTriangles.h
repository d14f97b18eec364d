#pragma once
// The triangles the bake traces (static instances, visible materials), in world space: what
// automatic placement voxelises and where the placement benchmark picks surface points.
// Same selection and face normals as RayScene (counter-clockwise front, flipped for
// mirroring instance transforms).
#include "scene/Scene.h"

#include <vector>

namespace pb::probes {

struct WorldTriangle {
    glm::vec3 a, b, c;
    glm::vec3 normal; // unit, front side
    bool doubleSided = false;
    float area() const { return 0.5f * glm::length(glm::cross(b - a, c - a)); }
};

// Degenerate triangles (zero area, bad indices) are left out.
std::vector<WorldTriangle> staticBakeTriangles(const scene::Scene& scene);

} // namespace pb::probes
