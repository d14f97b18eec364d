#include "probes/ProbeVolume.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace pb::probes {

glm::vec3 ProbeVolume::cellSize() const {
    glm::vec3 c;
    for (int a = 0; a < 3; ++a)
        c[a] = counts[a] > 1 ? 2.0f * halfExtents[a] / float(counts[a] - 1) : 2.0f * halfExtents[a];
    return c;
}

float ProbeVolume::minCellSize() const {
    glm::vec3 c = cellSize();
    float m = -1.0f;
    for (int a = 0; a < 3; ++a)
        if (counts[a] > 1) m = m < 0.0f ? c[a] : std::min(m, c[a]);
    return m > 0.0f ? m : std::min(c.x, std::min(c.y, c.z));
}

float ProbeVolume::maxDistance() const {
    return kMaxDistanceScale * glm::length(cellSize());
}

glm::ivec3 ProbeVolume::probeCoords(int index) const {
    int x = index % counts.x;
    int rest = index / counts.x;
    return {x, rest / counts.z, rest % counts.z};
}

glm::vec3 ProbeVolume::gridLocal(const glm::ivec3& c) const {
    glm::vec3 cell = cellSize(), p;
    for (int a = 0; a < 3; ++a)
        p[a] = counts[a] > 1 ? -halfExtents[a] + float(c[a]) * cell[a] : 0.0f;
    return p;
}

glm::vec3 ProbeVolume::toLocal(const glm::vec3& world) const {
    return glm::conjugate(rotation) * (world - center);
}

bool ProbeVolume::contains(const glm::vec3& world, float margin) const {
    glm::vec3 l = toLocal(world);
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(l[a]) <= halfExtents[a] + margin)) return false;
    return true;
}

std::vector<glm::vec3> ProbeVolume::worldCorners() const {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 s((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
        out.push_back(toWorld(s * halfExtents));
    }
    return out;
}

namespace {
std::string vecText(const glm::vec3& v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace

std::string volumeProblem(const ProbeVolume& v) {
    if (v.name.empty()) return "volume name is empty";
    for (int a = 0; a < 3; ++a) {
        if (v.counts[a] < 1)
            return "probe counts must be at least 1 per axis (got " + std::to_string(v.counts.x) +
                   "x" + std::to_string(v.counts.y) + "x" + std::to_string(v.counts.z) + ")";
        if (v.counts[a] > kMaxProbesPerAxis)
            return "at most " + std::to_string(kMaxProbesPerAxis) + " probes per axis";
    }
    if ((long long)v.counts.x * v.counts.y * v.counts.z > kMaxProbesPerVolume)
        return "more than " + std::to_string(kMaxProbesPerVolume) + " probes in one volume";
    if (!finite(v.center)) return "center is not finite";
    if (!finite(v.halfExtents) || v.halfExtents.x <= 0.0f || v.halfExtents.y <= 0.0f ||
        v.halfExtents.z <= 0.0f)
        return "half extents must be positive (got " + vecText(v.halfExtents) + ")";
    // Beyond these, cell sizes and their inverses leave the float range (NaN in the bake).
    if (glm::any(glm::greaterThan(glm::abs(v.center), glm::vec3(1e10f))))
        return "center is beyond 1e10";
    if (glm::any(glm::greaterThan(v.halfExtents, glm::vec3(1e10f))) ||
        glm::any(glm::lessThan(v.halfExtents, glm::vec3(1e-6f))))
        return "half extents must lie in [1e-6, 1e10] (got " + vecText(v.halfExtents) + ")";
    if (!(v.edgeBlend >= 0.0f && v.edgeBlend <= 1.0f)) return "edge_blend must be in [0, 1]";
    float ql = glm::length(glm::vec4(v.rotation.x, v.rotation.y, v.rotation.z, v.rotation.w));
    if (!std::isfinite(ql) || std::abs(ql - 1.0f) > 1e-3f)
        return "rotation is not a unit quaternion";
    return "";
}

std::string nestingProblem(const ProbeVolume& child, const ProbeVolume& parent) {
    // Relative tolerance so a child flush with its parent's face is accepted.
    float tol = 1e-4f * glm::length(parent.halfExtents);
    for (const glm::vec3& c : child.worldCorners())
        if (!parent.contains(c, tol))
            return "volume '" + child.name + "' is not inside its parent '" + parent.name +
                   "' (corner " + vecText(c) + " lies outside)";
    return "";
}

std::vector<int> validateVolumes(const std::vector<ProbeVolume>& volumes,
                                 const std::string& source) {
    std::map<std::string, int> byName;
    for (size_t i = 0; i < volumes.size(); ++i) {
        std::string p = volumeProblem(volumes[i]);
        if (!p.empty()) throw fileError(source, "volume '" + volumes[i].name + "': " + p);
        if (!byName.emplace(volumes[i].name, int(i)).second)
            throw fileError(source, "duplicate volume name '" + volumes[i].name + "'");
    }
    std::vector<int> parents(volumes.size(), -1);
    for (size_t i = 0; i < volumes.size(); ++i) {
        if (volumes[i].parent.empty()) continue;
        auto it = byName.find(volumes[i].parent);
        if (it == byName.end())
            throw fileError(source, "volume '" + volumes[i].name + "': unknown parent '" +
                                        volumes[i].parent + "'");
        parents[i] = it->second;
    }
    for (size_t i = 0; i < volumes.size(); ++i) {
        int steps = 0;
        for (int p = parents[i]; p >= 0; p = parents[size_t(p)])
            if (++steps > int(volumes.size()))
                throw fileError(source, "volume '" + volumes[i].name + "': parent chain loops");
        if (parents[i] >= 0) {
            std::string p = nestingProblem(volumes[i], volumes[size_t(parents[i])]);
            if (!p.empty()) throw fileError(source, p);
        }
    }
    return parents;
}

std::vector<int> parentFirstOrder(const std::vector<int>& parents) {
    auto depth = [&](int i) {
        int d = 0;
        for (int p = parents[size_t(i)]; p >= 0 && d <= int(parents.size()); p = parents[size_t(p)])
            ++d;
        return d;
    };
    std::vector<int> order(parents.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = int(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth(a) < depth(b); });
    return order;
}

glm::quat rotationFromEulerDegrees(const glm::vec3& deg) {
    glm::vec3 r = glm::radians(deg);
    glm::quat qx = glm::angleAxis(r.x, glm::vec3(1, 0, 0));
    glm::quat qy = glm::angleAxis(r.y, glm::vec3(0, 1, 0));
    glm::quat qz = glm::angleAxis(r.z, glm::vec3(0, 0, 1));
    return glm::normalize(qy * qx * qz);
}

} // namespace pb::probes
