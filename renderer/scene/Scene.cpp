#include "scene/Scene.h"

namespace pb::scene {

namespace {

// True when every row of the upper 3x3 has at most one non-zero entry (axis permutations,
// mirrors and scales): the transformed corners of a box then bound it exactly.
bool isAxisAligned(const glm::mat4& m) {
    for (int row = 0; row < 3; ++row) {
        int nonZero = 0;
        for (int col = 0; col < 3; ++col)
            if (m[col][row] != 0.0f) ++nonZero;
        if (nonZero > 1) return false;
    }
    return true;
}

// Exact world bounds of one instance. Rotated instances go vertex by vertex (a rotated box
// of the local bounds can be up to sqrt(3) too large, which would misplace probe volumes
// and the default view).
Bounds instanceBounds(const Primitive& prim, const glm::mat4& m) {
    Bounds b;
    if (prim.localBounds.empty()) return b;
    if (isAxisAligned(m)) {
        const glm::vec3 lo = prim.localBounds.min, hi = prim.localBounds.max;
        b.extend(glm::vec3(m * glm::vec4(lo, 1.0f)));
        b.extend(glm::vec3(m * glm::vec4(hi, 1.0f)));
        return b;
    }
    for (const glm::vec3& p : prim.positions)
        b.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
    return b;
}

Bounds boundsOf(const Scene& s, bool staticOnly) {
    Bounds b;
    for (const Instance& inst : s.instances) {
        if (staticOnly && inst.dynamic) continue;
        b.extend(instanceBounds(s.primitives[size_t(inst.primitive)], inst.transform));
    }
    return b;
}

} // namespace

Bounds Scene::worldBounds() const {
    return boundsOf(*this, false);
}

Bounds Scene::staticWorldBounds() const {
    return boundsOf(*this, true);
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Instance& inst : instances)
        n += primitives[size_t(inst.primitive)].triangleCount();
    return n;
}

const View* Scene::findView(const std::string& name) const {
    for (const View& v : views)
        if (v.name == name) return &v;
    return nullptr;
}

glm::vec3 worldPosition(const Scene& s, const Instance& inst, std::uint32_t vertex) {
    const glm::vec3& p = s.primitives[size_t(inst.primitive)].positions[vertex];
    return glm::vec3(inst.transform * glm::vec4(p, 1.0f));
}

} // namespace pb::scene
