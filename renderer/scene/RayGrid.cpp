#include "scene/RayGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb::scene {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kMaxDim = 128; // 2 M cells at most: a few MB for the largest scenes

// floor(v) as a cell index in [0, dims - 1]; clamped as floats first, so that NaN or a value
// beyond the int range (a degenerate or hostile scene) never reaches an int conversion.
glm::ivec3 clampedCell(const glm::vec3& v, const glm::ivec3& dims) {
    glm::ivec3 c;
    for (int a = 0; a < 3; ++a) {
        const float f = std::floor(v[a]);
        c[a] = f >= 0.0f ? (f < float(dims[a] - 1) ? int(f) : dims[a] - 1) : 0;
    }
    return c;
}
} // namespace

RayGrid::RayGrid(const Scene& scene) {
    size_t count = 0;
    for (const Instance& inst : scene.instances)
        count += scene.primitives[size_t(inst.primitive)].triangleCount();
    tris_.reserve(count);
    for (const Instance& inst : scene.instances) {
        if (inst.dynamic) continue;
        const Primitive& p = scene.primitives[size_t(inst.primitive)];
        if (scene.materials[size_t(p.material)].invisible()) continue;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
        for (size_t i = 0; i + 2 < p.indices.size(); i += 3) {
            const std::uint32_t a = p.indices[i], b = p.indices[i + 1], c = p.indices[i + 2];
            Tri t;
            t.v0 = worldPosition(scene, inst, a);
            t.e1 = worldPosition(scene, inst, b) - t.v0;
            t.e2 = worldPosition(scene, inst, c) - t.v0;
            t.facing = glm::cross(t.e1, t.e2);
            const Material& m = scene.materials[size_t(p.material)];
            t.emissive = m.emissive != glm::vec3(0.0f);
            if (t.emissive) emitters_.push_back(t.v0 + (t.e1 + t.e2) / 3.0f);
            if (m.doubleSided)
                t.facing = glm::vec3(0.0f); // both sides are front sides
            else if (!p.normals.empty() &&
                     glm::dot(t.facing,
                              normalMatrix * (p.normals[a] + p.normals[b] + p.normals[c])) < 0)
                t.facing = -t.facing;
            tris_.push_back(t);
            bounds_.extend(t.v0);
            bounds_.extend(t.v0 + t.e1);
            bounds_.extend(t.v0 + t.e2);
        }
    }
    const glm::vec3 size = bounds_.size();
    if (!std::isfinite(size.x + size.y + size.z)) tris_.clear(); // loaders reject such scenes
    if (!tris_.empty()) build();
}

void RayGrid::build() {
    // About one cell per triangle, cells as close to cubes as the bounds allow. Every side
    // gets a positive size, even when all triangles collapse to one point (relative to the
    // position, so that it stays representable far from the origin).
    const glm::vec3 far = glm::max(glm::abs(bounds_.min), glm::abs(bounds_.max));
    const float minSide = std::max(
        {1e-3f * glm::length(bounds_.size()), 1e-6f, 1e-6f * std::max({far.x, far.y, far.z})});
    const glm::vec3 size = glm::max(bounds_.size(), glm::vec3(minSide));
    // In double: the product of three tiny sides underflows a float.
    const double cell = std::cbrt(double(size.x) * size.y * size.z / double(tris_.size()));
    for (int a = 0; a < 3; ++a)
        dims_[a] = int(std::clamp(std::ceil(double(size[a]) / cell), 1.0, double(kMaxDim)));
    cellSize_ = size / glm::vec3(dims_);
    bounds_.max = bounds_.min + size;

    // Every cell the triangle's bounding box touches.
    auto forEachCell = [&](const Tri& t, auto&& fn) {
        const glm::vec3 a = t.v0, b = t.v0 + t.e1, c = t.v0 + t.e2;
        const glm::vec3 mn = glm::min(a, glm::min(b, c)) - bounds_.min;
        const glm::vec3 mx = glm::max(a, glm::max(b, c)) - bounds_.min;
        const glm::ivec3 lo = clampedCell(mn / cellSize_, dims_);
        const glm::ivec3 hi = clampedCell(mx / cellSize_, dims_);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    fn(cellIndex(glm::ivec3(x, y, z)));
    };
    // Count, then fill: all lists live in one array, no per-cell allocations.
    const size_t cells = size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z);
    cellStart_.assign(cells + 1, 0);
    for (const Tri& t : tris_)
        forEachCell(t, [&](size_t c) { ++cellStart_[c + 1]; });
    for (size_t c = 0; c < cells; ++c)
        cellStart_[c + 1] += cellStart_[c];
    cellTris_.resize(cellStart_[cells]);
    std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
    for (size_t i = 0; i < tris_.size(); ++i)
        forEachCell(tris_[i], [&](size_t c) { cellTris_[next[c]++] = std::uint32_t(i); });
}

size_t RayGrid::cellIndex(const glm::ivec3& cell) const {
    return (size_t(cell.z) * size_t(dims_.y) + size_t(cell.y)) * size_t(dims_.x) + size_t(cell.x);
}

RayHit RayGrid::cast(const glm::vec3& o, const glm::vec3& d, float maxDistance) const {
    RayHit best{kInf, false};
    if (tris_.empty()) return best;
    // Clip the ray to the grid box.
    float t0 = 0.0f, t1 = maxDistance;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / d[a];
        float tn = (bounds_.min[a] - o[a]) * inv, tf = (bounds_.max[a] - o[a]) * inv;
        if (tn > tf) std::swap(tn, tf);
        if (!std::isnan(tn)) t0 = std::max(t0, tn);
        if (!std::isnan(tf)) t1 = std::min(t1, tf);
    }
    if (t0 > t1) return best;
    // Walk the cells the ray crosses, nearest first (Amanatides & Woo).
    const glm::vec3 start = (o + d * t0 - bounds_.min) / cellSize_;
    glm::ivec3 cell = clampedCell(start, dims_);
    glm::ivec3 step;
    glm::vec3 tNext, tDelta;
    for (int a = 0; a < 3; ++a) {
        step[a] = d[a] > 0 ? 1 : -1;
        tDelta[a] = d[a] != 0.0f ? cellSize_[a] / std::abs(d[a]) : kInf;
        const float boundary = bounds_.min[a] + float(cell[a] + (d[a] > 0 ? 1 : 0)) * cellSize_[a];
        tNext[a] = d[a] != 0.0f ? (boundary - o[a]) / d[a] : kInf;
    }
    const float minDistance = 1e-5f * glm::length(bounds_.size());
    while (true) {
        const size_t c = cellIndex(cell);
        for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
            const Tri& t = tris_[cellTris_[k]];
            const glm::vec3 p = glm::cross(d, t.e2);
            const float det = glm::dot(t.e1, p);
            if (std::abs(det) < 1e-20f) continue;
            const float inv = 1.0f / det;
            const glm::vec3 s = o - t.v0;
            const float u = glm::dot(s, p) * inv;
            if (u < 0.0f || u > 1.0f) continue;
            const glm::vec3 q = glm::cross(s, t.e1);
            const float v = glm::dot(d, q) * inv;
            if (v < 0.0f || u + v > 1.0f) continue;
            const float dist = glm::dot(t.e2, q) * inv;
            if (dist > minDistance && dist <= maxDistance && dist < best.distance) {
                glm::vec3 n = glm::normalize(glm::cross(t.e1, t.e2));
                if (glm::dot(n, d) > 0.0f) n = -n;
                best = {dist, glm::dot(t.facing, d) > 0.0f, n, t.emissive};
            }
        }
        // A hit inside this cell cannot be beaten by any later cell.
        const int a = tNext.x < tNext.y ? (tNext.x < tNext.z ? 0 : 2) : (tNext.y < tNext.z ? 1 : 2);
        if (best.distance <= tNext[a] || tNext[a] > t1) break;
        cell[a] += step[a];
        if (cell[a] < 0 || cell[a] >= dims_[a]) break;
        tNext[a] += tDelta[a];
    }
    return best;
}

} // namespace pb::scene
