#include "probes/store/SparseStorage.h"

#include "core/Error.h"
#include "probes/ProbeSampler.h"
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

std::vector<std::uint8_t> surfaceCornerProbes(const ProbeVolume& v, bool root,
                                              const std::vector<WorldTriangle>& triangles) {
    std::vector<std::uint8_t> needed(std::size_t(v.probeCount()), 0);
    const glm::vec3 cell = v.cellSize(), h = v.halfExtents;
    const glm::vec3 fade = root ? kEdgeFadeCells * cell : glm::vec3(0.0f);
    // Cells grow by kSurfaceCellMargin so a surface on or near a cell face keeps the cells on
    // both sides: shading positions sit a little off their surface (GBuffer depth precision,
    // the placement benchmark's 1e-4 scene offset) and the sampler's rounding decides the cell.
    const glm::vec3 eps = kSurfaceCellMargin * cell;
    const glm::ivec3 cells = glm::max(v.counts - 1, glm::ivec3(1));
    // Extent of cell `b` along axis a, widened into the fade margin at the volume's faces.
    auto cellLo = [&](int a, int b) {
        return v.counts[a] == 1 || b == 0 ? -h[a] - fade[a] : -h[a] + float(b) * cell[a];
    };
    auto cellHi = [&](int a, int b) {
        return v.counts[a] == 1 || b == cells[a] - 1 ? h[a] + fade[a]
                                                     : -h[a] + float(b + 1) * cell[a];
    };
    auto cellIndex = [&](int a, float x) {
        if (v.counts[a] == 1) return 0;
        return int(std::floor(std::clamp((x + h[a]) / cell[a], 0.0f, float(v.counts[a] - 2))));
    };
    for (const WorldTriangle& wt : triangles) {
        const glm::vec3 t[3] = {v.toLocal(wt.a), v.toLocal(wt.b), v.toLocal(wt.c)};
        const glm::vec3 lo = glm::min(t[0], glm::min(t[1], t[2])) - eps;
        const glm::vec3 hi = glm::max(t[0], glm::max(t[1], t[2])) + eps;
        if (glm::any(glm::greaterThan(lo, h + fade)) || glm::any(glm::lessThan(hi, -h - fade)))
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
                        boxLo[a] = cellLo(a, b[a]) - eps[a];
                        boxHi[a] = cellHi(a, b[a]) + eps[a];
                    }
                    if (!triangleOverlapsBox(t, 0.5f * (boxLo + boxHi), 0.5f * (boxHi - boxLo)))
                        continue;
                    for (int o = 0; o < 8; ++o) {
                        const glm::ivec3 q = b + glm::ivec3(o & 1, (o >> 1) & 1, (o >> 2) & 1);
                        if (glm::all(glm::lessThan(q, v.counts)))
                            needed[std::size_t(v.probeIndex(q))] = 1;
                    }
                }
    }
    return needed;
}

std::vector<std::uint8_t> freeSpaceLatticeProbes(const ProbeVolume& v) {
    std::vector<std::uint8_t> out(std::size_t(v.probeCount()), 0);
    for (int i = 0; i < v.probeCount(); ++i) {
        const glm::ivec3 q = v.probeCoords(i);
        out[std::size_t(i)] = q.x % kFreeSpaceLatticeStep == 0 &&
                              q.y % kFreeSpaceLatticeStep == 0 &&
                              q.z % kFreeSpaceLatticeStep == 0;
    }
    return out;
}

std::vector<std::uint8_t> sparseKeptProbes(const ProbeVolume& v, bool root,
                                           const std::vector<WorldTriangle>& triangles) {
    std::vector<std::uint8_t> keep = surfaceCornerProbes(v, root, triangles);
    const std::vector<std::uint8_t> lattice = freeSpaceLatticeProbes(v);
    for (std::size_t i = 0; i < keep.size(); ++i)
        keep[i] |= lattice[i];
    return keep;
}

std::size_t freeSpaceOnlyProbes(const ProbeSet& set,
                                const std::vector<WorldTriangle>& triangles) {
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

std::vector<std::size_t> sparseProbeCounts(const std::vector<ProbeVolume>& volumes,
                                           const std::vector<WorldTriangle>& triangles) {
    const std::vector<int> parents = validateVolumes(volumes, "sparse storage");
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        std::vector<std::uint8_t> m = sparseKeptProbes(volumes[i], parents[i] < 0, triangles);
        out.push_back(std::size_t(std::count(m.begin(), m.end(), std::uint8_t(1))));
    }
    return out;
}

void applySparseStorage(ProbeSet& set, const std::vector<WorldTriangle>& triangles) {
    const std::vector<int> parents = validateVolumes(set.volumes, "sparse storage");
    std::vector<std::vector<std::uint8_t>> keep;
    for (std::size_t vi = 0; vi < set.volumes.size(); ++vi)
        keep.push_back(sparseKeptProbes(set.volumes[vi], parents[vi] < 0, triangles));
    storeOnly(set, keep);
}

void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep) {
    if (keep.size() != set.volumes.size()) throw Error("storeOnly: one mask per volume");
    for (std::size_t vi = 0; vi < set.volumes.size(); ++vi) {
        const ProbeVolume& v = set.volumes[vi];
        std::vector<ProbeState>& states = set.states[vi];
        if (keep[vi].size() != states.size()) throw Error("storeOnly: one flag per probe");
        for (std::size_t i = 0; i < states.size(); ++i) {
            states[i].stored = states[i].valid && keep[vi][i];
            states[i].valid = states[i].stored;
        }
        // Zero what is not stored the way the file's round trip does: pack, then unpack.
        const std::vector<int> slots = packedSlots(states);
        const glm::ivec3 packed = packedCounts(storedCount(states), v.counts);
        auto roundTrip = [&](ProbeTexture& t, int tile) {
            t = unpackTiles(packTiles(t, slots, v.counts, packed, tile, set.format()), slots,
                            v.counts, packed, tile, set.format());
        };
        roundTrip(set.visibility[vi], kVisibilityTile);
        for (auto& scenario : set.irradiance)
            roundTrip(scenario[vi], kIrradianceTile);
    }
}

} // namespace pb::probes
