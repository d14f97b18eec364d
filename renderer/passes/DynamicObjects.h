#pragma once
// The scene's dynamic objects as gi.dynamic=sh sees them: one object per dynamic glTF node
// (its instances share the node name; a dynamic node's children are objects of their own),
// numbered in instance order. The GBuffer's flags channel carries the number of a dynamic
// pixel's object in bits 1-7 (bit 0: dynamic), so at most kMaxShObjects get their own SH.
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::render {

inline constexpr int kMaxShObjects = 128;

struct DynamicObject {
    std::string name;
    std::vector<int> instances;
    scene::Bounds bounds; // world, of the instances' transformed local boxes
    glm::dvec3 centre() const { return glm::dvec3(bounds.center()); }
};

struct DynamicObjects {
    std::vector<DynamicObject> objects;
    std::vector<int> objectOfInstance; // per scene instance; -1 for static ones
};

DynamicObjects findDynamicObjects(const scene::Scene& s);

// The GBuffer flags value (bits) of one instance: 0 static, else 1 | (object << 1) with the
// object number clamped to kMaxShObjects - 1.
unsigned gbufferFlagBits(const DynamicObjects& d, int instance);

} // namespace pb::render
