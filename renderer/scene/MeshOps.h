#pragma once
// Geometry helpers shared by the glTF loader and the built-in scenes.
#include "scene/Scene.h"

namespace pb::scene {

// Smooth per-vertex normals from the indexed triangles: each triangle adds its un-normalised
// cross product (area-weighted) to its three vertices. Zero-area triangles add nothing;
// a vertex no triangle lends a direction to gets +Y, so the result never holds NaN.
void generateSmoothNormals(Primitive& prim);

// Normalises the normals in place; returns false (and leaves them unusable) when one is
// zero-length or not finite, so the caller can regenerate them.
bool normalizeNormals(std::vector<glm::vec3>& normals);

Bounds computeBounds(const std::vector<glm::vec3>& positions);

} // namespace pb::scene
