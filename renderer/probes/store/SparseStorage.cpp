#include "probes/store/SparseStorage.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "probes/ProbeSampler.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/SparseLayout.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {
namespace {

// Separating-axis test of a triangle against an axis-aligned box (centre c, half size e):
// the box's 3 axes, the triangle's normal and the 9 edge x axis cross products.
bool triangleOverlapsBox(const glm::vec3 t[3], const glm::vec3& c, const glm::vec3& e) {
    const glm::vec3 v[3] = {t[0] - c, t[1] - c, t[2] - c};
    auto separated = [&](const glm::vec3& axis) {
        const float r = e.x * std::abs(axis.x) + e.y * std::abs(axis.y) + e.z * std::abs(axis.z);
        const float p0 = glm::dot(v[0], axis), p1 = glm::dot(v[1], axis), p2 = glm::dot(v[2], axis);
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };
    for (int a = 0; a < 3; ++a) {
        glm::vec3 axis(0.0f);
        axis[a] = 1.0f;
        if (separated(axis)) return false;
    }
    const glm::vec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    if (separated(glm::cross(edges[0], edges[1]))) return false;
    for (const glm::vec3& edge : edges)
        for (int a = 0; a < 3; ++a) {
            glm::vec3 axis(0.0f);
            axis[a] = 1.0f;
            if (separated(glm::cross(edge, axis))) return false;
        }
    return true;
}

} // namespace

namespace {

// Marks the corners of the cells of `v` that the triangles [first, last) pass through.
class SurfaceCells {
public:
    SurfaceCells(const ProbeVolume& v, bool root)
        : v_(v), cell_(v.cellSize()), h_(v.halfExtents),
          fade_(root ? kEdgeFadeCells * cell_ : glm::vec3(0.0f)),
          // Cells grow by kSurfaceCellMargin so a surface on or near a cell face keeps the
          // cells on both sides: shading positions sit a little off their surface (GBuffer
          // depth precision, the placement benchmark's 1e-4 scene offset) and the sampler's
          // rounding decides the cell.
          eps_(kSurfaceCellMargin * cell_), cells_(glm::max(v.counts - 1, glm::ivec3(1))) {}

    void mark(const raytrace::WorldTriangle* first, const raytrace::WorldTriangle* last,
              std::vector<std::uint8_t>& needed) const {
        for (const raytrace::WorldTriangle* wt = first; wt != last; ++wt) {
            const glm::vec3 t[3] = {local(wt->a), local(wt->b), local(wt->c)};
            const glm::vec3 tLo = glm::min(t[0], glm::min(t[1], t[2]));
            const glm::vec3 tHi = glm::max(t[0], glm::max(t[1], t[2]));
            const glm::vec3 lo = tLo - eps_, hi = tHi + eps_;
            if (glm::any(glm::greaterThan(lo, h_ + fade_)) ||
                glm::any(glm::lessThan(hi, -h_ - fade_)))
                continue;
            glm::ivec3 b0, b1;
            for (int a = 0; a < 3; ++a) {
                b0[a] = cellIndex(a, lo[a]);
                b1[a] = cellIndex(a, hi[a]);
            }
            glm::ivec3 b;
            for (b.y = b0.y; b.y <= b1.y; ++b.y)
                for (b.z = b0.z; b.z <= b1.z; ++b.z)
                    for (b.x = b0.x; b.x <= b1.x; ++b.x) {
                        glm::vec3 boxLo, boxHi;
                        for (int a = 0; a < 3; ++a) {
                            boxLo[a] = cellLo(a, b[a]) - eps_[a];
                            boxHi[a] = cellHi(a, b[a]) + eps_[a];
                        }
                        // A triangle inside the box overlaps it: most triangles are small
                        // against a cell, and the separating-axis test is the costly part.
                        const bool inside = glm::all(glm::greaterThanEqual(tLo, boxLo)) &&
                                            glm::all(glm::lessThanEqual(tHi, boxHi));
                        if (!inside &&
                            !triangleOverlapsBox(t, 0.5f * (boxLo + boxHi), 0.5f * (boxHi - boxLo)))
                            continue;
                        for (int o = 0; o < 8; ++o) {
                            const glm::ivec3 q = b + glm::ivec3(o & 1, (o >> 1) & 1, (o >> 2) & 1);
                            if (glm::all(glm::lessThan(q, v_.counts)))
                                needed[std::size_t(v_.probeIndex(q))] = 1;
                        }
                    }
        }
    }

private:
    // v.toLocal, without the rotation for an axis-aligned volume (every auto volume): glm's
    // quaternion rotation adds exact zeros then, so the result is the same float for float.
    glm::vec3 local(const glm::vec3& world) const {
        return aligned_ ? world - v_.center : v_.toLocal(world);
    }
    // Extent of cell `b` along axis a, widened into the fade margin at the volume's faces.
    float cellLo(int a, int b) const {
        return v_.counts[a] == 1 || b == 0 ? -h_[a] - fade_[a] : -h_[a] + float(b) * cell_[a];
    }
    float cellHi(int a, int b) const {
        return v_.counts[a] == 1 || b == cells_[a] - 1 ? h_[a] + fade_[a]
                                                       : -h_[a] + float(b + 1) * cell_[a];
    }
    int cellIndex(int a, float x) const {
        if (v_.counts[a] == 1) return 0;
        return int(std::floor(std::clamp((x + h_[a]) / cell_[a], 0.0f, float(v_.counts[a] - 2))));
    }

    const ProbeVolume& v_;
    const glm::vec3 cell_, h_, fade_, eps_;
    const glm::ivec3 cells_;
    const bool aligned_ = v_.rotation == glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
};

// Triangles per work item: large enough that merging the per-thread masks stays cheap.
constexpr std::size_t kTrianglesPerItem = 8192;

} // namespace

std::vector<std::uint8_t> surfaceCornerProbes(const ProbeVolume& v, bool root,
                                              const std::vector<raytrace::WorldTriangle>& triangles) {
    const std::size_t probes = std::size_t(v.probeCount());
    const SurfaceCells cells(v, root);
    const std::size_t items = (triangles.size() + kTrianglesPerItem - 1) / kTrianglesPerItem;
    const int threads = int(
        std::min<std::size_t>(std::size_t(resolveThreadCount(0)), std::max<std::size_t>(items, 1)));
    // One mask per thread, OR-ed at the end: marking only ever sets, so the result does not
    // depend on which thread saw which triangle (the placement calls this for every candidate
    // and every trial bake, so it runs on all cores).
    std::vector<std::vector<std::uint8_t>> masks(std::size_t(threads),
                                                 std::vector<std::uint8_t>(probes, 0));
    parallelFor(items, threads, [&](std::size_t item, int t) {
        const std::size_t first = item * kTrianglesPerItem;
        const std::size_t last = std::min(triangles.size(), first + kTrianglesPerItem);
        cells.mark(triangles.data() + first, triangles.data() + last, masks[std::size_t(t)]);
    });
    std::vector<std::uint8_t> needed = std::move(masks[0]);
    for (std::size_t t = 1; t < masks.size(); ++t)
        for (std::size_t i = 0; i < probes; ++i)
            needed[i] |= masks[t][i];
    return needed;
}

std::vector<std::uint8_t> freeSpaceLatticeProbes(const ProbeVolume& v) {
    std::vector<std::uint8_t> out(std::size_t(v.probeCount()), 0);
    for (int i = 0; i < v.probeCount(); ++i) {
        const glm::ivec3 q = v.probeCoords(i);
        out[std::size_t(i)] = q.x % kFreeSpaceLatticeStep == 0 &&
                              q.y % kFreeSpaceLatticeStep == 0 && q.z % kFreeSpaceLatticeStep == 0;
    }
    return out;
}

std::vector<std::uint8_t> sparseKeptProbes(const ProbeVolume& v, bool root,
                                           const std::vector<raytrace::WorldTriangle>& triangles) {
    std::vector<std::uint8_t> keep = surfaceCornerProbes(v, root, triangles);
    const std::vector<std::uint8_t> lattice = freeSpaceLatticeProbes(v);
    for (std::size_t i = 0; i < keep.size(); ++i)
        keep[i] |= lattice[i];
    return keep;
}

std::size_t freeSpaceOnlyProbes(const ProbeSet& set, const std::vector<raytrace::WorldTriangle>& triangles) {
    const std::vector<int> parents = validateVolumes(set.volumes, "sparse storage");
    std::size_t n = 0;
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        const std::vector<std::uint8_t> surface =
            surfaceCornerProbes(set.volumes[v], parents[v] < 0, triangles);
        const std::vector<std::uint8_t> lattice = freeSpaceLatticeProbes(set.volumes[v]);
        for (std::size_t i = 0; i < surface.size() && i < set.states[v].size(); ++i)
            n += set.states[v][i].stored && lattice[i] && !surface[i] ? 1 : 0;
    }
    return n;
}

std::vector<std::vector<std::uint8_t>>
sparseKeptMasks(const std::vector<ProbeVolume>& volumes,
                const std::vector<raytrace::WorldTriangle>& triangles) {
    const std::vector<int> parents = validateVolumes(volumes, "sparse storage");
    std::vector<std::vector<std::uint8_t>> out;
    for (std::size_t i = 0; i < volumes.size(); ++i)
        out.push_back(sparseKeptProbes(volumes[i], parents[i] < 0, triangles));
    return out;
}

std::vector<std::size_t> keptCounts(const std::vector<std::vector<std::uint8_t>>& masks) {
    std::vector<std::size_t> out;
    for (const std::vector<std::uint8_t>& m : masks)
        out.push_back(std::size_t(std::count(m.begin(), m.end(), std::uint8_t(1))));
    return out;
}

std::vector<std::size_t> sparseProbeCounts(const std::vector<ProbeVolume>& volumes,
                                           const std::vector<raytrace::WorldTriangle>& triangles) {
    return keptCounts(sparseKeptMasks(volumes, triangles));
}

const char* freeSpaceName(FreeSpace f) {
    switch (f) {
    case FreeSpace::StandIns: return "stand-ins";
    case FreeSpace::Ranked: return "ranked";
    case FreeSpace::Irradiance: return "all";
    }
    return "?";
}

bool parseFreeSpace(const std::string& text, FreeSpace& out) {
    for (FreeSpace f : {FreeSpace::StandIns, FreeSpace::Ranked, FreeSpace::Irradiance})
        if (text == freeSpaceName(f)) {
            out = f;
            return true;
        }
    return false;
}

void applySparseStorage(ProbeSet& set, const std::vector<raytrace::WorldTriangle>& triangles,
                        FreeSpace freeSpace, double budgetBytes) {
    const std::vector<int> parents = validateVolumes(set.volumes, "sparse storage");
    std::vector<std::vector<std::uint8_t>> keep;
    for (std::size_t vi = 0; vi < set.volumes.size(); ++vi)
        keep.push_back(sparseKeptProbes(set.volumes[vi], parents[vi] < 0, triangles));
    storeOnly(set, keep, freeSpace, budgetBytes);
}

void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep,
               FreeSpace freeSpace, double budgetBytes) {
    if (freeSpace == FreeSpace::Ranked) {
        storeOnly(set, keep, chooseFreeSpaceTiles(set, keep, budgetBytes).tiles);
        return;
    }
    std::vector<std::vector<std::uint8_t>> tiles;
    for (const auto& k : keep)
        tiles.emplace_back(k.size(), freeSpace == FreeSpace::Irradiance ? 1 : 0);
    storeOnly(set, keep, tiles);
}

void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep,
               const std::vector<std::vector<std::uint8_t>>& tiles) {
    if (keep.size() != set.volumes.size() || tiles.size() != set.volumes.size())
        throw Error("storeOnly: one mask per volume");
    for (std::size_t vi = 0; vi < set.volumes.size(); ++vi) {
        const ProbeVolume& v = set.volumes[vi];
        std::vector<ProbeState>& states = set.states[vi];
        if (keep[vi].size() != states.size() || tiles[vi].size() != states.size())
            throw Error("storeOnly: one flag per probe");
        // A valid probe left out with a tile keeps its irradiance (ProbeState::irradianceOnly):
        // it lies outside geometry, and only free cells read it. Otherwise, and for an invalid
        // probe, it is dropped whole.
        for (std::size_t i = 0; i < states.size(); ++i) {
            const bool valid = states[i].valid;
            states[i].stored = valid && keep[vi][i];
            states[i].irradianceOnly = valid && !keep[vi][i] && tiles[vi][i];
            states[i].valid = states[i].stored || states[i].irradianceOnly;
        }
        // Zero what is not stored the way the file's round trip (pack, then unpack) does.
        zeroUnslottedTiles(set.visibility[vi], packedSlots(states), v.counts, kVisibilityTile,
                           set.format());
        for (auto& scenario : set.irradiance)
            zeroUnslottedTiles(scenario[vi], irradianceSlots(states), v.counts, kIrradianceTile,
                               set.format());
        // The SH record keeps the probes with irradiance (ProbeFile.cpp): the rest read zeros.
        for (auto& scenario : set.sh)
            for (std::size_t p = 0; p < states.size() && vi < scenario.size(); ++p)
                if (!ownsIrradiance(states[p]))
                    std::fill_n(scenario[vi].begin() + std::ptrdiff_t(p * kShL2Coefficients),
                                kShL2Coefficients, glm::vec3(0.0f));
    }
}

} // namespace pb::probes
