#pragma once
// The parts of a scene every input hash takes the same way: the bake's (BakeHash.cpp) and the
// path-traced truth's cache (renderer/truth). One definition, so a light field added to the
// scene cannot be hashed by one and forgotten by the other.
#include "core/Hash.h"
#include "scene/Scene.h"

#include <vector>

namespace pb::raytrace {

void hashSun(Hasher& h, const scene::Sun& sun);
void hashLights(Hasher& h, const std::vector<scene::Light>& lights);
// Material index, vertex positions and triangle indices (not normals or UVs).
void hashPrimitiveGeometry(Hasher& h, const scene::Primitive& p);

} // namespace pb::raytrace
