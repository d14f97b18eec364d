#include "probes/placement/AdaptivePlacement.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "probes/bake/RayDirections.h"
#include "probes/placement/AutoVolume.h"
#include "probes/placement/BoxMerge.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace pb::probes {
namespace {

using Cell = glm::ivec3;

// The octree over the outer volume: level-l cells are the outer cells split 2^l times.
struct Lattice {
    glm::dvec3 origin, size; // outer box min and size
    glm::ivec3 outerCells;   // cells of level 0 per axis
    int levels;

    glm::ivec3 cells(int level) const { return outerCells * (1 << level); }
    glm::dvec3 cellSize(int level) const { return size / glm::dvec3(cells(level)); }
    // Finest-lattice key of point q of level `level` (corner keys are shared across levels).
    std::uint64_t pointKey(const Cell& q, int level) const {
        glm::ivec3 f = q * (1 << (levels - level));
        glm::ivec3 n = cells(levels) + 1;
        return (std::uint64_t(f.x) * std::uint64_t(n.y) + std::uint64_t(f.y)) * std::uint64_t(n.z) +
               std::uint64_t(f.z);
    }
    glm::vec3 pointFromKey(std::uint64_t key) const {
        glm::ivec3 n = cells(levels) + 1;
        std::uint64_t z = key % std::uint64_t(n.z);
        key /= std::uint64_t(n.z);
        std::uint64_t y = key % std::uint64_t(n.y), x = key / std::uint64_t(n.y);
        return glm::vec3(origin + glm::dvec3(double(x), double(y), double(z)) * cellSize(levels));
    }
    std::uint64_t cellKey(const Cell& c, int level) const {
        glm::ivec3 n = cells(level);
        return (std::uint64_t(c.y) * std::uint64_t(n.z) + std::uint64_t(c.z)) * std::uint64_t(n.x) +
               std::uint64_t(c.x);
    }
};

// Sorted keys of the finest cells the triangles pass through, per level (coarser levels are
// the finest cells shifted down). Sampled: ~2 points per finest cell length on each triangle
// plus its corners, deterministic per triangle.
std::vector<std::vector<std::uint64_t>> occupiedCells(const Lattice& L,
                                                      const std::vector<raytrace::WorldTriangle>& tris) {
    const glm::dvec3 cell = L.cellSize(L.levels);
    const double minCell = std::min(cell.x, std::min(cell.y, cell.z));
    const glm::ivec3 nf = L.cells(L.levels);
    // The finest cells hit, as a bitmap over the finest grid where it is small enough (a bit
    // per cell, its index the cell's key): reading it in order gives the sorted distinct keys
    // that sorting every sample gave (the samples repeat each cell many times; the sort was
    // about a tenth of the apartment's placement time). Larger grids sort the samples' keys.
    const std::uint64_t cellCount =
        std::uint64_t(nf.x) * std::uint64_t(nf.y) * std::uint64_t(nf.z);
    constexpr std::uint64_t kBitmapCells = std::uint64_t(1) << 28; // 32 MiB
    const bool bitmap = cellCount <= kBitmapCells;
    std::vector<std::uint64_t> hit(bitmap ? std::size_t((cellCount + 63) / 64) : 0, 0);
    std::vector<std::uint64_t> sampled; // the keys, without the bitmap
    auto add = [&](const glm::vec3& p) {
        glm::dvec3 f = (glm::dvec3(p) - L.origin) / cell;
        Cell c;
        for (int a = 0; a < 3; ++a)
            c[a] = std::clamp(int(std::floor(f[a])), 0, nf[a] - 1);
        const std::uint64_t key = L.cellKey(c, L.levels);
        if (bitmap)
            hit[std::size_t(key >> 6)] |= std::uint64_t(1) << (key & 63);
        else
            sampled.push_back(key);
    };
    for (std::size_t t = 0; t < tris.size(); ++t) {
        const raytrace::WorldTriangle& w = tris[t];
        add(w.a);
        add(w.b);
        add(w.c);
        double n = std::ceil(4.0 * double(w.area()) / (minCell * minCell));
        long long samples = (long long)std::min(n, 65536.0);
        std::uint64_t state = 0x51ED2701u ^ (std::uint64_t(t) * 0x9E3779B97F4A7C15ull);
        for (long long i = 0; i < samples; ++i) {
            float u = uniformFloat(state), v = uniformFloat(state);
            if (u + v > 1.0f) {
                u = 1.0f - u;
                v = 1.0f - v;
            }
            add(w.a + u * (w.b - w.a) + v * (w.c - w.a));
        }
    }
    // The finest level first; the coarser ones from its distinct cells only.
    std::vector<std::vector<std::uint64_t>> out(size_t(L.levels) + 1);
    auto sortedUnique = [](std::vector<std::uint64_t>& keys) {
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    };
    std::vector<std::uint64_t>& fine = out[size_t(L.levels)];
    if (bitmap) {
        for (std::size_t w = 0; w < hit.size(); ++w)
            for (std::uint64_t bits = hit[w]; bits != 0; bits &= bits - 1)
                fine.push_back(std::uint64_t(w) * 64 + std::uint64_t(__builtin_ctzll(bits)));
    } else {
        fine = std::move(sampled);
        sortedUnique(fine);
    }
    std::vector<Cell> distinct;
    distinct.reserve(fine.size());
    for (std::uint64_t key : fine) { // key = (y * n.z + z) * n.x + x (Lattice::cellKey)
        Cell c;
        c.x = int(key % std::uint64_t(nf.x));
        c.z = int((key / std::uint64_t(nf.x)) % std::uint64_t(nf.z));
        c.y = int(key / std::uint64_t(nf.x) / std::uint64_t(nf.z));
        distinct.push_back(c);
    }
    for (int l = 0; l < L.levels; ++l) {
        auto& keys = out[size_t(l)];
        keys.reserve(distinct.size());
        for (const Cell& f : distinct)
            keys.push_back(L.cellKey(f / (1 << (L.levels - l)), l));
        sortedUnique(keys);
    }
    return out;
}

// Harmonic-mean distance to surfaces from each point (keys sorted, unique).
void harmonicMeanDistances(const raytrace::RayScene& rays, const Lattice& L,
                           const std::vector<std::uint64_t>& keys,
                           const std::vector<glm::vec3>& dirs, int threads,
                           std::unordered_map<std::uint64_t, float>& out) {
    std::vector<float> hm(keys.size());
    const float minDistance = 1e-6f * float(std::max(L.size.x, std::max(L.size.y, L.size.z)));
    parallelFor(keys.size(), threads, [&](std::size_t i, int) {
        glm::vec3 p = L.pointFromKey(keys[i]);
        double inverseSum = 0.0;
        for (const glm::vec3& d : dirs) {
            raytrace::RayHit h = rays.intersect(p, d);
            if (h.hit()) inverseSum += 1.0 / double(std::max(h.t, minDistance));
        }
        hm[i] = inverseSum > 0.0 ? float(double(dirs.size()) / inverseSum)
                                 : std::numeric_limits<float>::infinity();
    });
    for (std::size_t i = 0; i < keys.size(); ++i)
        out.emplace(keys[i], hm[i]);
}

struct Parent {
    int volume;        // index into the result
    glm::ivec3 lo, hi; // cells of its own level
};

ProbeVolume boxVolume(const Lattice& L, int level, const glm::ivec3& lo, const glm::ivec3& hi,
                      std::string name, std::string parent) {
    const glm::dvec3 cell = L.cellSize(level);
    ProbeVolume v;
    v.name = std::move(name);
    v.parent = std::move(parent);
    v.center = glm::vec3(L.origin + glm::dvec3(lo + hi) * 0.5 * cell);
    v.halfExtents = glm::vec3(glm::dvec3(hi - lo) * 0.5 * cell);
    v.counts = hi - lo + 1;
    return v;
}

} // namespace

AdaptivePlacement placeAdaptiveVolumes(const raytrace::RayScene& rays,
                                       const std::vector<raytrace::WorldTriangle>& triangles,
                                       const scene::Bounds& bounds, const AdaptiveOptions& o) {
    if (!(o.spacing > 0.0f) || !std::isfinite(o.spacing))
        throw Error("--volumes auto: the finest spacing must be a positive number");
    if (o.levels < 1 || o.levels > 4) throw Error("--auto-levels: must be 1..4");
    if (o.cornerRays < 1) throw Error("--volumes auto: corner rays must be >= 1");
    if (o.maxChildren < 1) throw Error("--auto-max-children: must be >= 1");

    // Outer volume: the uniform fit at the coarse spacing (no probe cap here: the caller's
    // budget loop coarsens).
    AutoVolume outer = fitAutoVolume(bounds, o.spacing * float(1 << o.levels), kMaxProbesPerVolume,
                                     o.lattice, o.levels);
    Lattice L;
    L.origin = glm::dvec3(outer.volume.center) - glm::dvec3(outer.volume.halfExtents);
    L.size = glm::dvec3(outer.volume.halfExtents) * 2.0;
    L.outerCells = outer.volume.counts - 1;
    L.levels = o.levels;

    AdaptivePlacement out;
    out.volumes.push_back(outer.volume);
    auto longest = [](const glm::dvec3& c) { return std::max(c.x, std::max(c.y, c.z)); };
    out.stats.outerSpacing = float(longest(L.cellSize(0)));
    out.stats.finestSpacing = float(longest(L.cellSize(o.levels)));

    const auto occupied = occupiedCells(L, triangles);
    std::uint64_t rotationState = 0xA5A5F00Du;
    const glm::mat3 rot = randomRotation(rotationState); // no direction along a world axis
    std::vector<glm::vec3> dirs = sphericalFibonacci(o.cornerRays);
    for (glm::vec3& d : dirs)
        d = rot * d;
    std::unordered_map<std::uint64_t, float> hm;

    // Octree: near-surface cells per level.
    std::vector<std::vector<Cell>> nearCells(size_t(o.levels) + 1);
    std::vector<Cell> candidates;
    for (int y = 0; y < L.outerCells.y; ++y)
        for (int z = 0; z < L.outerCells.z; ++z)
            for (int x = 0; x < L.outerCells.x; ++x)
                candidates.push_back({x, y, z});
    for (int l = 0; l <= o.levels; ++l) {
        std::vector<std::uint64_t> missing;
        for (const Cell& c : candidates)
            for (int k = 0; k < 8; ++k) {
                std::uint64_t key = L.pointKey(c + Cell(k & 1, (k >> 1) & 1, k >> 2), l);
                if (!hm.count(key)) missing.push_back(key);
            }
        std::sort(missing.begin(), missing.end());
        missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
        harmonicMeanDistances(rays, L, missing, dirs, o.threads, hm);
        out.stats.corners += (long long)missing.size();
        out.stats.rays += (long long)missing.size() * o.cornerRays;

        const float threshold = o.nearFactor * float(longest(L.cellSize(l)));
        const auto& occ = occupied[size_t(l)];
        for (const Cell& c : candidates) {
            bool near = std::binary_search(occ.begin(), occ.end(), L.cellKey(c, l));
            for (int k = 0; k < 8 && !near; ++k)
                near = hm.at(L.pointKey(c + Cell(k & 1, (k >> 1) & 1, k >> 2), l)) < threshold;
            if (near) nearCells[size_t(l)].push_back(c);
        }
        out.stats.cellsTested.push_back((long long)candidates.size());
        out.stats.cellsNear.push_back((long long)nearCells[size_t(l)].size());
        candidates.clear();
        for (const Cell& c : nearCells[size_t(l)])
            for (int k = 0; k < 8; ++k)
                candidates.push_back(c * 2 + Cell(k & 1, (k >> 1) & 1, k >> 2));
    }

    // Tiers: near cells of level t, merged into boxes inside the tier t-1 volume they fall in.
    // A box that fills its whole parent would only duplicate it at a finer spacing: the
    // parent is refined to that spacing instead (an enclosed scene ends as one fine grid).
    std::vector<Parent> parents{{0, glm::ivec3(0), L.outerCells}};
    BoxMergeOptions merge;
    merge.maxBoxes = o.maxChildren;
    merge.pad = o.pad;
    for (int t = 1; t <= o.levels; ++t) {
        std::vector<std::vector<Cell>> byParent(parents.size());
        for (const Cell& c : nearCells[size_t(t)]) {
            Cell up = c / 2;
            for (std::size_t p = 0; p < parents.size(); ++p)
                if (glm::all(glm::greaterThanEqual(up, parents[p].lo)) &&
                    glm::all(glm::lessThan(up, parents[p].hi))) {
                    byParent[p].push_back(c);
                    break;
                }
        }
        std::vector<Parent> next;
        int serial = 0;
        for (std::size_t p = 0; p < parents.size(); ++p) {
            const auto& cells = byParent[p];
            if (cells.empty()) continue;
            glm::ivec3 lo = cells[0], hi = cells[0] + 1;
            for (const Cell& c : cells) {
                lo = glm::min(lo, c);
                hi = glm::max(hi, c + 1);
            }
            const glm::ivec3 dims = hi - lo;
            std::vector<std::uint8_t> marked(std::size_t(dims.x) * dims.y * dims.z, 0);
            for (const Cell& c : cells)
                marked[cellIndex(dims, c - lo)] = 1;
            const glm::ivec3 clipLo = parents[p].lo * 2, clipHi = parents[p].hi * 2;
            std::vector<std::pair<glm::ivec3, glm::ivec3>> boxes;
            bool fillsParent = false;
            for (const CellBox& b : mergeMarkedCells(dims, marked, merge)) {
                glm::ivec3 blo = glm::max(lo + b.lo - o.pad, clipLo);
                glm::ivec3 bhi = glm::min(lo + b.hi + o.pad, clipHi);
                fillsParent = fillsParent || (blo == clipLo && bhi == clipHi);
                boxes.emplace_back(blo, bhi);
            }
            ProbeVolume& parentVolume = out.volumes[size_t(parents[p].volume)];
            if (fillsParent) {
                parentVolume.counts = clipHi - clipLo + 1;
                next.push_back({parents[p].volume, clipLo, clipHi});
                continue;
            }
            for (const auto& [blo, bhi] : boxes) {
                out.volumes.push_back(boxVolume(
                    L, t, blo, bhi, "auto_" + std::to_string(t) + "_" + std::to_string(serial++),
                    out.volumes[size_t(parents[p].volume)].name));
                next.push_back({int(out.volumes.size()) - 1, blo, bhi});
            }
        }
        parents = std::move(next);
    }
    return out;
}

} // namespace pb::probes
