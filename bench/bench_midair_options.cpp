// bench_midair_options: how sparse storage lights points in the air, option by option (issue 18,
// bench/results/2026-11-25-mid-air-worst.md). A benchmark, not a test: it prints tables and
// asserts nothing; every figure is hardware-independent (deterministic bakes and lookups).
//
// Per built-in scene, the setting of tests/unit/MidAirLookupTest.cpp: one root volume over the
// static bounds (--max-probes, default 1500), baked dense (--rays, default 64; 2 bounces), and
// the same set stored sparse; 500 free-space points x 6 axis normals; error = |L - L_dense| /
// max(L_dense, a tenth of the scene's mean mid-air L_dense) over the lookups the kept sparse
// lookup changes. It prints
//   - the 10 worst lookups of the kept option: point, normal, dense and sparse luminance, grid
//     coordinates, distance to the nearest surface (26 rays, in cells) and per corner S
//     (stored), I (inside geometry) or F+dx+dy+dz (absent, read as the stored probe that far);
//   - the options: the kept fill (nearest stored probe), a trilinear lookup on the step-2
//     lattice itself in cells with absent corners (a coarse volume of the lattice probes, their
//     visibility rescaled to its range), the stored set grown by 1 or 2 probes around every
//     surface corner (with and without that coarse lookup), the lattice alone everywhere, and
//     stand-ins ranked with a penalty for surface-corner probes, and a coarse parent volume
//     over the lattice's points baked and stored dense, read where the sparse child's cell has
//     absent corners (stored counts: child + parent);
//   - what growing by 1 costs in the default placement (`--volumes auto`, sparse, no lattice
//     search): probes stored with and without it.
//
// Usage: bench_midair_options [--max-probes N] [--rays R] [SCENE...]  (default: cornell rooms
//        courtyard)
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/Baker.h"
#include "probes/bake/MidAirSamples.h"
#include "probes/bake/RayScene.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

using namespace pb::probes;

namespace {
int gMaxProbes = 1500; // the grid of tests/unit/MidAirLookupTest.cpp
int gRays = 64;
} // namespace

namespace {

float lum(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}
const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

struct Q {
    glm::vec3 p, n;
    float dense;
};

void stats(const char* scene, const char* name, const std::vector<Q>& qs, float floor,
           const std::function<IrradianceSample(const Q&)>& f, std::size_t stored,
           std::size_t total) {
    std::vector<float> rel;
    double sum = 0;
    int unlit = 0;
    for (const Q& q : qs) {
        IrradianceSample s = f(q);
        if (!(s.weight > 0)) ++unlit;
        rel.push_back(std::abs(lum(s.irradiance) - q.dense) / std::max(q.dense, floor));
        sum += rel.back();
    }
    std::sort(rel.begin(), rel.end());
    auto pc = [&](int p) { return rel[rel.size() * p / 100]; };
    std::printf("| %s | %s | %zu / %zu | %zu | %.4f | %.4f | %.4f | %.4f | unlit %d |\n", name,
                scene, stored, total, rel.size(), sum / rel.size(), pc(90), pc(99), rel.back(),
                unlit);
}

// A coarse volume over the step-2 lattice of `v` (grown by one fine cell on axes whose
// count - 1 is odd; the lattice point beyond the grid is invalid), tiles copied from `set`.
struct Coarse {
    ProbeVolume vol;
    std::vector<ProbeState> states;
    ProbeTexture irr, vis;
};
Coarse makeCoarse(const ProbeSet& set, const std::vector<ProbeState>& st) {
    const ProbeVolume& v = set.volumes[0];
    Coarse c;
    c.vol = v;
    const glm::vec3 cell = v.cellSize();
    glm::vec3 shift(0);
    for (int a = 0; a < 3; ++a) {
        const int n = v.counts[a];
        const bool odd = (n - 1) % 2 != 0;
        c.vol.counts[a] = (n - 1 + (odd ? 1 : 0)) / 2 + 1;
        if (odd) {
            c.vol.halfExtents[a] += 0.5f * cell[a];
            shift[a] = 0.5f * cell[a];
        }
    }
    c.vol.center = v.center + v.rotation * shift;
    c.irr = ProbeTexture::make(irradianceShape(c.vol.counts));
    c.vis = ProbeTexture::make(visibilityShape(c.vol.counts));
    c.irr.storageScale = set.irradiance[0][0].storageScale;
    c.states.resize(std::size_t(c.vol.probeCount()));
    const float scale = v.maxDistance() / c.vol.maxDistance();
    for (int i = 0; i < c.vol.probeCount(); ++i) {
        const glm::ivec3 cc = c.vol.probeCoords(i), fc = cc * 2;
        if (glm::any(glm::greaterThanEqual(fc, v.counts))) {
            c.states[std::size_t(i)].valid = false;
            continue;
        }
        const ProbeState& s = st[std::size_t(v.probeIndex(fc))];
        c.states[std::size_t(i)] = s;
        for (int y = 0; y < kIrradianceTile; ++y)
            for (int x = 0; x < kIrradianceTile; ++x)
                std::copy_n(set.irradiance[0][0].at(fc.x * kIrradianceTile + x,
                                                    fc.z * kIrradianceTile + y, fc.y),
                            kIrradianceChannels,
                            c.irr.at(cc.x * kIrradianceTile + x, cc.z * kIrradianceTile + y, cc.y));
        for (int y = 0; y < kVisibilityTile; ++y)
            for (int x = 0; x < kVisibilityTile; ++x) {
                const float* src = set.visibility[0].at(fc.x * kVisibilityTile + x,
                                                        fc.z * kVisibilityTile + y, fc.y);
                float* dst = c.vis.at(cc.x * kVisibilityTile + x, cc.z * kVisibilityTile + y, cc.y);
                dst[0] = src[0] * scale;
                dst[1] = src[1] * scale * scale;
            }
    }
    return c;
}

bool anyFillable(const ProbeSet& s, const glm::vec3& pos) {
    const ProbeVolume& v = s.volumes[0];
    const glm::vec3 g = (v.toLocal(pos) + v.halfExtents) / v.cellSize();
    glm::ivec3 b;
    for (int a = 0; a < 3; ++a)
        b[a] = std::clamp(int(std::floor(g[a])), 0, v.counts[a] - 2);
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 q = b + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        if (fillable(s.states[0][std::size_t(v.probeIndex(q))], s.settings.backfaceThreshold))
            return true;
    }
    return false;
}

// The mid-air lookups (500 free-space points x 6 axis normals) whose sparse lookup differs
// from the dense one at all (stand-ins read, or other probes), and the error floor: a tenth of
// the scene's mean dense luminance over all of them.
struct ChangedQueries {
    std::vector<Q> queries;
    float floor = 0.0f;
};

ChangedQueries changedQueries(const RayScene& rs, const ProbeSet& dense, const ProbeSampler& ds,
                              const ProbeSampler& ss) {
    ChangedQueries out;
    double total = 0;
    std::size_t all = 0;
    for (const glm::vec3& p : midAirSamples(rs, dense.volumes, 500, dense.volumes[0].minCellSize()))
        for (const glm::vec3& n : kAxes) {
            const IrradianceSample d = ds.sample(p, n, n), s = ss.sample(p, n, n);
            total += lum(d.irradiance);
            ++all;
            if (s.filled == 0 && s.probes == d.probes) continue;
            out.queries.push_back({p, n, lum(d.irradiance)});
        }
    out.floor = 0.1f * float(total / double(all));
    return out;
}

// The built-in scene's dense bake of one root volume over its static bounds, and the same set
// stored sparse (what a sparse bake of that grid gives).
struct DenseAndSparse {
    pb::scene::Scene scene;
    BakeRequest request;
    std::vector<WorldTriangle> tris;
    ProbeSet dense, sparse;
};

DenseAndSparse bakeDenseAndSparse(const char* name) {
    DenseAndSparse b;
    b.scene = pb::scene::makeBuiltinScene(name);
    BakeRequest& r = b.request;
    r.volumes.push_back(fitAutoVolume(staticBakeBounds(b.scene), 0.0f, gMaxProbes).volume);
    r.scenarios = resolveScenarios({"day"}, {}, b.scene);
    r.settings.raysPerProbe = gRays;
    r.settings.bounces = 2;
    b.dense = bakeProbes(b.scene, r);
    b.tris = staticBakeTriangles(b.scene);
    b.sparse = b.dense;
    applySparseStorage(b.sparse, b.tris);
    return b;
}

void run(const char* name) {
    DenseAndSparse b = bakeDenseAndSparse(name);
    const BakeRequest& r = b.request;
    const pb::scene::Scene& scene = b.scene;
    const ProbeSet& dense = b.dense;
    const auto& tris = b.tris;
    ProbeSet& sparse = b.sparse;
    const ProbeVolume& v = dense.volumes[0];
    std::printf("%s: counts %d %d %d cell %.3f %.3f %.3f\n", name, v.counts.x, v.counts.y,
                v.counts.z, v.cellSize().x, v.cellSize().y, v.cellSize().z);
    const RayScene rs(scene);
    const ProbeSampler ds(dense, 0), ss(sparse, 0);
    const ChangedQueries cq = changedQueries(rs, dense, ds, ss);
    const std::vector<Q>& changed = cq.queries;
    const float floor = cq.floor;

    // 1. The 10 worst of the kept option.
    {
        std::vector<std::pair<float, Q>> w;
        for (const Q& q : changed)
            w.push_back({std::abs(lum(ss.sample(q.p, q.n, q.n).irradiance) - q.dense) /
                             std::max(q.dense, floor),
                         q});
        std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.first > b.first; });
        const std::vector<int> src =
            fillSources(v, sparse.states[0], sparse.settings.backfaceThreshold);
        for (int i = 0; i < 10 && i < int(w.size()); ++i) {
            const Q& q = w[size_t(i)].second;
            const glm::vec3 g = (v.toLocal(q.p) + v.halfExtents) / v.cellSize();
            glm::ivec3 b;
            for (int a = 0; a < 3; ++a)
                b[a] = std::clamp(int(std::floor(g[a])), 0, v.counts[a] - 2);
            float near = 1e9f;
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (!dx && !dy && !dz) continue;
                        const RayHit h = rs.intersect(q.p, glm::normalize(glm::vec3(dx, dy, dz)));
                        if (h.hit()) near = std::min(near, h.t);
                    }
            std::printf("  #%d rel %.3f p (%.2f %.2f %.2f) n (%g %g %g) dense %.4f sparse %.4f "
                        "grid (%.2f %.2f %.2f) surf %.2f cells; corners:",
                        i, w[size_t(i)].first, q.p.x, q.p.y, q.p.z, q.n.x, q.n.y, q.n.z, q.dense,
                        lum(ss.sample(q.p, q.n, q.n).irradiance), g.x, g.y, g.z,
                        near / v.minCellSize());
            for (int c = 0; c < 8; ++c) {
                const glm::ivec3 k = b + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
                const int idx = v.probeIndex(k);
                const ProbeState& s = sparse.states[0][size_t(idx)];
                if (s.stored)
                    std::printf(" S");
                else if (!fillable(s, sparse.settings.backfaceThreshold))
                    std::printf(" I");
                else {
                    const glm::ivec3 sc = v.probeCoords(src[size_t(idx)]);
                    std::printf(" F%+d%+d%+d", sc.x - k.x, sc.y - k.y, sc.z - k.z);
                }
            }
            std::printf("\n");
        }
    }

    const std::size_t N = dense.probeCount();
    std::printf("| option | scene | stored / grid | lookups | mean | p90 | p99 | worst | |\n");
    stats(
        name, "kept: lattice + nearest", changed, floor,
        [&](const Q& q) { return ss.sample(q.p, q.n, q.n); }, sparse.storedCount(), N);

    // 2a. Coarse lattice lookup where the fine cell has a fillable corner.
    const Coarse co = makeCoarse(sparse, sparse.states[0]);
    const ProbeSampler cs(
        std::vector<SamplerVolume>{{&co.vol, co.states.data(), &co.irr, &co.vis, true,
                                    std::numeric_limits<float>::quiet_NaN()}});
    stats(
        name, "coarse lattice lookup in cells with absent corners", changed, floor,
        [&](const Q& q) {
            return anyFillable(sparse, q.p) ? cs.sample(q.p, q.n, q.n) : ss.sample(q.p, q.n, q.n);
        },
        sparse.storedCount(), N);

    // 3. Grow: keep every probe within g steps of a surface corner.
    for (int grow = 1; grow <= 2; ++grow) {
        std::vector<std::uint8_t> surf = surfaceCornerProbes(v, true, tris);
        std::vector<std::uint8_t> keep = sparseKeptProbes(v, true, tris);
        for (int i = 0; i < v.probeCount(); ++i) {
            if (!surf[size_t(i)]) continue;
            const glm::ivec3 c = v.probeCoords(i);
            for (int dz = -grow; dz <= grow; ++dz)
                for (int dy = -grow; dy <= grow; ++dy)
                    for (int dx = -grow; dx <= grow; ++dx) {
                        const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                        if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                            glm::any(glm::greaterThanEqual(q, v.counts)))
                            continue;
                        keep[size_t(v.probeIndex(q))] = 1;
                    }
        }
        ProbeSet grown = dense;
        storeOnly(grown, {keep});
        const ProbeSampler gs(grown, 0);
        char label[64];
        std::snprintf(label, sizeof label, "grow surface corners by %d", grow);
        stats(
            name, label, changed, floor, [&](const Q& q) { return gs.sample(q.p, q.n, q.n); },
            grown.storedCount(), N);
        const Coarse gc = makeCoarse(grown, grown.states[0]);
        const ProbeSampler gcs(
            std::vector<SamplerVolume>{{&gc.vol, gc.states.data(), &gc.irr, &gc.vis, true,
                                        std::numeric_limits<float>::quiet_NaN()}});
        std::snprintf(label, sizeof label, "grow %d + coarse lookup", grow);
        stats(
            name, label, changed, floor,
            [&](const Q& q) {
                return anyFillable(grown, q.p) ? gcs.sample(q.p, q.n, q.n)
                                               : gs.sample(q.p, q.n, q.n);
            },
            grown.storedCount(), N);
    }
    // Reference: the coarse lattice alone everywhere (a dense step-2 volume).
    stats(
        name, "coarse lattice everywhere (ref)", changed, floor,
        [&](const Q& q) { return cs.sample(q.p, q.n, q.n); }, co.vol.probeCount(), N);

    // A coarse parent volume stored dense (its own bake over the lattice's points, with its
    // own visibility range), read where the sparse child's cell has an absent corner; the
    // child stores its surface corners and the lattice (as kept) or the surface corners only.
    BakeRequest pr = r;
    pr.volumes = {co.vol};
    const ProbeSet parent = bakeProbes(scene, pr);
    const ProbeSampler ps(parent, 0);
    stats(
        name, "dense coarse parent where the child cell has absent corners", changed, floor,
        [&](const Q& q) {
            return anyFillable(sparse, q.p) ? ps.sample(q.p, q.n, q.n) : ss.sample(q.p, q.n, q.n);
        },
        sparse.storedCount() + parent.storedCount(), N);
    ProbeSet surfaceOnly = dense;
    storeOnly(surfaceOnly, {surfaceCornerProbes(v, true, tris)});
    const ProbeSampler so(surfaceOnly, 0);
    stats(
        name, "dense coarse parent + child of surface corners only", changed, floor,
        [&](const Q& q) {
            return anyFillable(surfaceOnly, q.p) ? ps.sample(q.p, q.n, q.n)
                                                 : so.sample(q.p, q.n, q.n);
        },
        surfaceOnly.storedCount() + parent.storedCount(), N);
}

} // namespace

#include "probes/placement/AutoPlacement.h"
namespace {
std::vector<std::uint8_t> grownKeep(const ProbeVolume& v, bool root,
                                    const std::vector<WorldTriangle>& tris, int grow) {
    std::vector<std::uint8_t> surf = surfaceCornerProbes(v, root, tris);
    std::vector<std::uint8_t> keep = sparseKeptProbes(v, root, tris);
    for (int i = 0; i < v.probeCount(); ++i) {
        if (!surf[size_t(i)]) continue;
        const glm::ivec3 c = v.probeCoords(i);
        for (int dz = -grow; dz <= grow; ++dz)
            for (int dy = -grow; dy <= grow; ++dy)
                for (int dx = -grow; dx <= grow; ++dx) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(q, v.counts)))
                        continue;
                    keep[size_t(v.probeIndex(q))] = 1;
                }
    }
    return keep;
}
void placementCost(const char* name) {
    pb::scene::Scene scene = pb::scene::makeBuiltinScene(name);
    AutoPlacementRequest req;
    req.sparse = true;
    req.latticeSearch = false;
    const AutoPlacementResult res = placeAutoVolumes(scene, req);
    const auto tris = staticBakeTriangles(scene);
    const std::vector<int> parents = validateVolumes(res.volumes, "x");
    std::size_t grid = 0, kept = 0, surf = 0, grown = 0;
    for (std::size_t i = 0; i < res.volumes.size(); ++i) {
        const ProbeVolume& v = res.volumes[i];
        const bool root = parents[i] < 0;
        grid += size_t(v.probeCount());
        auto cnt = [](const std::vector<std::uint8_t>& m) {
            return std::size_t(std::count(m.begin(), m.end(), std::uint8_t(1)));
        };
        kept += cnt(sparseKeptProbes(v, root, tris));
        surf += cnt(surfaceCornerProbes(v, root, tris));
        grown += cnt(grownKeep(v, root, tris, 1));
    }
    std::printf("[ cost ] %s default placement (no lattice search): %zu volumes, grid %zu, "
                "surface corners %zu, kept (surface + lattice) %zu, grown by 1 %zu (+%.1f%%), "
                "placement bytes %zu\n",
                name, res.volumes.size(), grid, surf, kept, grown,
                100.0 * (double(grown) / double(kept) - 1.0), res.bytes);
}
} // namespace

namespace {
// Emulates a fill with the given sources: filled probes become stored copies of their source.
ProbeSet emulateFill(const ProbeSet& sparse, const std::vector<int>& src) {
    ProbeSet out = sparse;
    const ProbeVolume& v = out.volumes[0];
    const std::vector<ProbeState> ls = lookupStates(v, sparse.states[0], src);
    for (int i = 0; i < v.probeCount(); ++i) {
        const int s = src[size_t(i)];
        if (s < 0 || s == i) continue;
        out.states[0][size_t(i)] = ls[size_t(i)];
        out.states[0][size_t(i)].stored = true;
        const glm::ivec3 a = v.probeCoords(i), b = v.probeCoords(s);
        for (int y = 0; y < kIrradianceTile; ++y)
            for (int x = 0; x < kIrradianceTile; ++x)
                std::copy_n(sparse.irradiance[0][0].at(b.x * kIrradianceTile + x,
                                                       b.z * kIrradianceTile + y, b.y),
                            kIrradianceChannels,
                            out.irradiance[0][0].at(a.x * kIrradianceTile + x,
                                                    a.z * kIrradianceTile + y, a.y));
        for (int y = 0; y < kVisibilityTile; ++y)
            for (int x = 0; x < kVisibilityTile; ++x)
                std::copy_n(sparse.visibility[0].at(b.x * kVisibilityTile + x,
                                                    b.z * kVisibilityTile + y, b.y),
                            kVisibilityChannels,
                            out.visibility[0].at(a.x * kVisibilityTile + x,
                                                 a.z * kVisibilityTile + y, a.y));
    }
    out.settings.backfaceThreshold = sparse.settings.backfaceThreshold;
    return out;
}
// Sources by a ranking within +-2 cells: cost = distance + penalty for surface corners.
std::vector<int> rankedSources(const ProbeSet& sp, const std::vector<std::uint8_t>& surf,
                               float surfacePenalty) {
    const ProbeVolume& v = sp.volumes[0];
    const auto& st = sp.states[0];
    std::vector<int> src(size_t(v.probeCount()));
    const glm::vec3 cell = v.cellSize();
    for (int i = 0; i < v.probeCount(); ++i) {
        src[size_t(i)] = i;
        if (!fillable(st[size_t(i)], sp.settings.backfaceThreshold)) continue;
        const glm::ivec3 c = v.probeCoords(i);
        float best = 1e30f;
        int bi = -1;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz)
                for (int dx = -2; dx <= 2; ++dx) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(q, v.counts)))
                        continue;
                    const int qi = v.probeIndex(q);
                    if (!(st[size_t(qi)].stored && st[size_t(qi)].valid)) continue;
                    const float d = glm::length(glm::vec3(dx, dy, dz) * cell) / v.minCellSize() +
                                    (surf[size_t(qi)] ? surfacePenalty : 0.0f);
                    if (d < best) {
                        best = d;
                        bi = qi;
                    }
                }
        src[size_t(i)] = bi;
    }
    return src;
}
void fillVariants(const char* name) {
    DenseAndSparse b = bakeDenseAndSparse(name);
    const pb::scene::Scene& scene = b.scene;
    const ProbeSet& dense = b.dense;
    const auto& tris = b.tris;
    ProbeSet& sparse = b.sparse;
    const ProbeVolume& v = dense.volumes[0];
    const RayScene rs(scene);
    const ProbeSampler ds(dense, 0), ss(sparse, 0);
    const ChangedQueries cq = changedQueries(rs, dense, ds, ss);
    const std::vector<Q>& changed = cq.queries;
    const float floor = cq.floor;
    stats(
        name, "kept: nearest", changed, floor, [&](const Q& q) { return ss.sample(q.p, q.n, q.n); },
        sparse.storedCount(), dense.probeCount());
    const std::vector<std::uint8_t> surf = surfaceCornerProbes(v, true, tris);
    for (float pen : {0.01f, 0.5f, 1.0f}) {
        const ProbeSet e = emulateFill(sparse, rankedSources(sparse, surf, pen));
        const ProbeSampler es(e, 0);
        char label[64];
        std::snprintf(label, sizeof label, "ranked, surface penalty %.2f cells", pen);
        stats(
            name, label, changed, floor, [&](const Q& q) { return es.sample(q.p, q.n, q.n); },
            sparse.storedCount(), dense.probeCount());
    }
}
} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--max-probes" && i + 1 < argc)
            gMaxProbes = std::atoi(argv[++i]);
        else if (a == "--rays" && i + 1 < argc)
            gRays = std::atoi(argv[++i]);
        else if (a.rfind("--", 0) == 0) {
            std::fprintf(stderr, "bench_midair_options: unknown option %s\n", a.c_str());
            return 2;
        } else
            scenes.push_back(a);
    }
    if (scenes.empty()) scenes = {"cornell", "rooms", "courtyard"};
    try {
        for (const std::string& s : scenes) {
            run(s.c_str());
            fillVariants(s.c_str());
            placementCost(s.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_midair_options: %s\n", e.what());
        return 1;
    }
    return 0;
}
