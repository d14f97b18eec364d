// bench_midair_options: how sparse storage lights points in the air, option by option (issue 18,
// studies/results/2026-11-25-mid-air-worst.md). A benchmark, not a test: it prints tables and
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
//   - absent probes outside geometry keeping an irradiance of their own, read at their own
//     position with visibility weight 1 (studies/results/2026-11-25-absent-sh.md), emulated
//     through the tile path (absentAsTile): the dense bake's L2 SH (ray projection; plain and
//     Hanning-windowed), L2/L3/L4 fits of the probe's 8x8 tile, the tile resampled to 2x2 and
//     4x4 interiors, the tile itself, and the tile next to surface corners with L2 elsewhere;
//     the 5 worst lookups of the L2 row with their absent corners' tile vs L2 luminance;
//   - what growing by 1 costs in the default placement (`--volumes auto`, sparse, no lattice
//     search): probes stored with and without it, and what an L2 SH or an 8x8 irradiance tile
//     per absent probe would add in bytes.
// --sh-only: the kept fill, the own-irradiance rows and the costs only.
// --slack: only irradiance-only tiles chosen after the bake for the left-out probes whose
// stand-in is furthest off, as many as a budget's slack buys (slackVariants).
//
// Usage: bench_midair_options [--max-probes N] [--rays R] [--sh-only | --slack]
//                             [--default-placement] [SCENE...]
//        (default: cornell rooms courtyard)
#include "core/Error.h"
#include "core/Luminance.h"
#include "core/ReuseFreedMemory.h"
#include "probes/AbsentProbeFill.h"
#include "probes/Octahedral.h"
#include "probes/ProbeSampler.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/StorageFormat.h"
#include "probes/bake/MidAirSamples.h"
#include "raytrace/RayScene.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"
#include "studies/common/StudyBake.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace pb::probes;

namespace {

// The command line (usage above).
struct Options {
    int maxProbes = 1500; // the grid of tests/unit/MidAirLookupTest.cpp
    int rays = 64;
    bool shOnly = false; // --sh-only: the kept fill, the own-irradiance rows and the costs
    bool slack = false;  // --slack: irradiance-only tiles chosen after the bake, only
    // --default-placement: the volume `bake --volumes auto` places by default (sparse, lattice
    // search) instead of the test's grid; its budget slack is reported (one volume only).
    bool defaultPlacement = false;
    std::vector<std::string> scenes;
};

} // namespace

namespace {

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
        rel.push_back(std::abs(pb::luminance(s.irradiance) - q.dense) / std::max(q.dense, floor));
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

// What an absent probe outside geometry keeps, emulated through the DDGI tile path: the dense
// set, its absent-in-sparse probes outside geometry never occluding (visibility mean far beyond
// the range: weight 1, as a probe of a free cell needs no visibility) and their irradiance tile
// replaced by `irradiance(probe, direction)` at its 6x6 interior texel centres (borders
// refilled); a null function keeps the baked tile. The lookup then filters those texels
// bilinearly, as it does every tile.
using AbsentIrradiance = std::function<glm::vec3(int probe, const glm::vec3& dir)>;
ProbeSet absentAsTile(const ProbeSet& dense, const ProbeSet& sparse, const AbsentIrradiance& fn) {
    ProbeSet out = dense;
    const ProbeVolume& v = dense.volumes[0];
    for (int i = 0; i < v.probeCount(); ++i) {
        if (!fillable(sparse.states[0][size_t(i)], sparse.settings.backfaceThreshold)) continue;
        const glm::ivec3 c = v.probeCoords(i);
        for (int y = 0; y < kVisibilityTile; ++y)
            for (int x = 0; x < kVisibilityTile; ++x) {
                float* t =
                    out.visibility[0].at(c.x * kVisibilityTile + x, c.z * kVisibilityTile + y, c.y);
                t[0] = 1e4f;
                t[1] = 1e8f;
            }
        if (!fn) continue;
        float* tile = tileOrigin(out.irradiance[0][0], c, kIrradianceTile);
        const int pitch = out.irradiance[0][0].shape.width;
        for (int y = 0; y < kIrradianceInterior; ++y)
            for (int x = 0; x < kIrradianceInterior; ++x) {
                const glm::vec3 e = fn(i, octTexelDirection(x, y, kIrradianceInterior));
                for (int ch = 0; ch < 3; ++ch)
                    tile[(size_t(y + 1) * size_t(pitch) + size_t(x + 1)) * 4 + size_t(ch)] = e[ch];
            }
        fillOctahedralBorder(tile, pitch, 4, kIrradianceInterior);
    }
    return out;
}

// The baked irradiance tile of probe `i` of `set` (volume 0) filtered at `dir`.
glm::vec3 tileIrradiance(const ProbeSet& set, int i, const glm::vec3& dir) {
    const glm::ivec3 c = set.volumes[0].probeCoords(i);
    const glm::vec2 tc = tileCoord(c, dir, kIrradianceInterior);
    float e[4];
    bilinearFetch(set.irradiance[0][0], tc.x, tc.y, c.y, e);
    return {e[0], e[1], e[2]};
}

// Per probe, a least-squares fit of its baked tile (filtered at 1024 directions) in spherical
// harmonics up to band `order` - the homogeneous polynomials of degree order and order - 1 span
// exactly those bands on the sphere, (order + 1)^2 functions - evaluated at `dir`, clamped at
// 0. Fits are made once per probe, on first use.
class TileFit {
public:
    TileFit(const ProbeSet& set, int order) : set_(set) {
        for (int deg = std::max(order - 1, 0); deg <= order; ++deg)
            for (int a = 0; a <= deg; ++a)
                for (int b = 0; a + b <= deg; ++b)
                    powers_.push_back({a, b, deg - a - b});
        coefficients_.resize(std::size_t(set.volumes[0].probeCount()));
    }
    glm::vec3 operator()(int i, const glm::vec3& dir) {
        std::vector<glm::dvec3>& x = coefficients_[std::size_t(i)];
        if (x.empty()) x = fit(i);
        const std::vector<double> f = basis(dir);
        glm::dvec3 e(0.0);
        for (std::size_t k = 0; k < f.size(); ++k)
            e += f[k] * x[k];
        return glm::max(glm::vec3(e), glm::vec3(0.0f));
    }

private:
    std::vector<double> basis(const glm::vec3& d) const {
        std::vector<double> f(powers_.size());
        for (std::size_t k = 0; k < f.size(); ++k)
            f[k] = std::pow(double(d.x), powers_[k].x) * std::pow(double(d.y), powers_[k].y) *
                   std::pow(double(d.z), powers_[k].z);
        return f;
    }
    // Normal equations (A^T A) x = A^T b, Gauss-Jordan with partial pivoting, in double.
    std::vector<glm::dvec3> fit(int i) const {
        const std::size_t m = powers_.size();
        std::vector<double> ata(m * m, 0.0);
        std::vector<glm::dvec3> atb(m, glm::dvec3(0.0));
        for (const glm::vec3& d : shProjectionDirections(1024)) {
            const glm::dvec3 e(tileIrradiance(set_, i, d));
            const std::vector<double> f = basis(d);
            for (std::size_t r = 0; r < m; ++r) {
                for (std::size_t q = 0; q < m; ++q)
                    ata[r * m + q] += f[r] * f[q];
                atb[r] += f[r] * e;
            }
        }
        for (std::size_t col = 0; col < m; ++col) {
            std::size_t piv = col;
            for (std::size_t r = col + 1; r < m; ++r)
                if (std::abs(ata[r * m + col]) > std::abs(ata[piv * m + col])) piv = r;
            for (std::size_t q = 0; q < m; ++q)
                std::swap(ata[col * m + q], ata[piv * m + q]);
            std::swap(atb[col], atb[piv]);
            for (std::size_t r = 0; r < m; ++r) {
                if (r == col) continue;
                const double k = ata[r * m + col] / ata[col * m + col];
                for (std::size_t q = 0; q < m; ++q)
                    ata[r * m + q] -= k * ata[col * m + q];
                atb[r] -= k * atb[col];
            }
        }
        for (std::size_t k = 0; k < m; ++k)
            atb[k] /= ata[k * m + k];
        return atb;
    }
    const ProbeSet& set_;
    std::vector<glm::ivec3> powers_;
    std::vector<std::vector<glm::dvec3>> coefficients_;
};

// Per probe, its baked tile resampled to a coarser octahedral map of `interior`^2 texels (the
// fine map filtered at the coarse texels' directions), read back bilinearly at `dir`: what a
// smaller irradiance tile would keep (pessimistic: two filterings).
class CoarseTile {
public:
    CoarseTile(const ProbeSet& set, int interior) : set_(set), interior_(interior) {}
    glm::vec3 operator()(int i, const glm::vec3& dir) const {
        const int tile = interior_ + 2;
        std::vector<float> t(std::size_t(tile * tile * 4), 0.0f);
        for (int y = 0; y < interior_; ++y)
            for (int x = 0; x < interior_; ++x) {
                const glm::vec3 e = tileIrradiance(set_, i, octTexelDirection(x, y, interior_));
                for (int ch = 0; ch < 3; ++ch)
                    t[(std::size_t(y + 1) * std::size_t(tile) + std::size_t(x + 1)) * 4 +
                      std::size_t(ch)] = e[ch];
            }
        fillOctahedralBorder(t.data(), tile, 4, interior_);
        ProbeTexture one = ProbeTexture::make({tile, tile, 1, 4});
        one.texels.assign(t.begin(), t.end());
        const glm::vec2 tc = tileCoord(glm::ivec3(0), dir, interior_);
        float e[4];
        bilinearFetch(one, tc.x, tc.y, 0, e);
        return {e[0], e[1], e[2]};
    }

private:
    const ProbeSet& set_;
    int interior_;
};

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

ChangedQueries changedQueries(const pb::raytrace::RayScene& rs, const ProbeSet& dense, const ProbeSampler& ds,
                              const ProbeSampler& ss) {
    ChangedQueries out;
    double total = 0;
    std::size_t all = 0;
    for (const glm::vec3& p : midAirSamples(rs, dense.volumes, 500, dense.volumes[0].minCellSize()))
        for (const glm::vec3& n : kAxes) {
            const IrradianceSample d = ds.sample(p, n, n), s = ss.sample(p, n, n);
            total += pb::luminance(d.irradiance);
            ++all;
            if (s.filled == 0 && s.probes == d.probes) continue;
            out.queries.push_back({p, n, pb::luminance(d.irradiance)});
        }
    out.floor = 0.1f * float(total / double(all));
    return out;
}

// The built-in scene's dense bake of one root volume over its static bounds, and the same set
// stored sparse: `sparse` as a default sparse bake of that grid gives it (the probes left out
// keep nothing and are read as stand-ins: the storage every option below is weighed against),

// `irradianceOnly` as `bake --free-space all` does (they keep their irradiance).
struct DenseAndSparse {
    pb::scene::Scene scene;
    pb::studies::BakeOptions bakeOptions;
    std::vector<pb::raytrace::WorldTriangle> tris;
    ProbeSet dense, sparse, irradianceOnly;
    double placementSlack = -1.0; // --default-placement: 1 - the placement's bytes / its budget
};

DenseAndSparse bakeDenseAndSparse(const char* name, const Options& o) {
    DenseAndSparse b;
    b.scene = pb::scene::makeBuiltinScene(name);
    pb::studies::BakeOptions& r = b.bakeOptions;
    if (o.defaultPlacement) {
        AutoPlacementRequest req;
        req.sparse = true;
        req.freeSpace = FreeSpace::Ranked; // as `bake` places: the slack includes the tiles' share
        const AutoPlacementResult a = placeAutoVolumes(b.scene, req);
        if (a.volumes.size() != 1)
            throw pb::Error(std::string(name) + ": the default placement has " +
                            std::to_string(a.volumes.size()) + " volumes (one only here)");
        r.volumes = a.volumes;
        b.placementSlack = 1.0 - double(a.bytes) / a.budgetBytes;
    } else {
        r.volumes.push_back(fitAutoVolume(pb::raytrace::staticBakeBounds(b.scene), 0.0f, o.maxProbes).volume);
    }
    r.scenarios = {"day"};
    r.rays = o.rays;
    r.bounces = 2;
    b.dense = pb::studies::bake(b.scene, r);
    b.tris = pb::raytrace::staticBakeTriangles(b.scene);
    b.irradianceOnly = b.sparse = b.dense;
    applySparseStorage(b.irradianceOnly, b.tris, FreeSpace::Irradiance);
    applySparseStorage(b.sparse, b.tris);
    return b;
}

// One built-in scene's bakes (bakeDenseAndSparse), the samplers over them and the mid-air
// lookups sparse storage changes: what every option below is weighed with. Built in place:
// the samplers read its bakes.
struct SceneContext {
    SceneContext(const char* sceneName, const Options& o)
        : name(sceneName), b(bakeDenseAndSparse(sceneName, o)), rs(b.scene), ds(b.dense, 0),
          ss(b.sparse, 0), cq(changedQueries(rs, b.dense, ds, ss)) {}
    SceneContext(const SceneContext&) = delete;
    SceneContext& operator=(const SceneContext&) = delete;

    const char* name;
    const DenseAndSparse b;
    const pb::raytrace::RayScene rs;
    const ProbeSampler ds, ss; // dense, sparse
    const ChangedQueries cq;
};

// The options table's columns (stats prints the rows).
void printOptionsHeader() {
    std::printf("| option | scene | stored / grid | lookups | mean | p90 | p99 | worst | |\n");
}

// A lookup on the coarse step-2 lattice of makeCoarse.
ProbeSampler coarseSampler(const Coarse& c) {
    return ProbeSampler(std::vector<SamplerVolume>{
        {&c.vol, c.states.data(), &c.irr, &c.vis, true, std::numeric_limits<float>::quiet_NaN()}});
}

void printGridCounts(const SceneContext& ctx) {
    const ProbeVolume& v = ctx.b.dense.volumes[0];
    std::printf("%s: counts %d %d %d cell %.3f %.3f %.3f\n", ctx.name, v.counts.x, v.counts.y,
                v.counts.z, v.cellSize().x, v.cellSize().y, v.cellSize().z);
}

// 1. The 10 worst lookups of the kept option, with their corners and stand-ins.
// The changed queries with `sampler`'s relative error against the dense lookup, worst first.
std::vector<std::pair<float, Q>> worstFirst(const ProbeSampler& sampler, const std::vector<Q>& changed,
                                            float floor) {
    std::vector<std::pair<float, Q>> w;
    for (const Q& q : changed)
        w.push_back({std::abs(pb::luminance(sampler.sample(q.p, q.n, q.n).irradiance) - q.dense) /
                         std::max(q.dense, floor),
                     q});
    std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.first > b.first; });
    return w;
}

void printWorstKeptLookups(const SceneContext& ctx) {
    const ProbeVolume& v = ctx.b.dense.volumes[0];
    const ProbeSet& sparse = ctx.b.sparse;
    const pb::raytrace::RayScene& rs = ctx.rs;
    const ProbeSampler& ss = ctx.ss;
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::vector<std::pair<float, Q>> w = worstFirst(ss, changed, floor);
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
                    const pb::raytrace::RayHit h = rs.intersect(q.p, glm::normalize(glm::vec3(dx, dy, dz)));
                    if (h.hit()) near = std::min(near, h.t);
                }
        std::printf("  #%d rel %.3f p (%.2f %.2f %.2f) n (%g %g %g) dense %.4f sparse %.4f "
                    "grid (%.2f %.2f %.2f) surf %.2f cells; corners:",
                    i, w[size_t(i)].first, q.p.x, q.p.y, q.p.z, q.n.x, q.n.y, q.n.z, q.dense,
                    pb::luminance(ss.sample(q.p, q.n, q.n).irradiance), g.x, g.y, g.z,
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

// The kept fill (stand-ins) and `--free-space all` (irradiance-only tiles for the left-out).
void printStandInRows(const SceneContext& ctx) {
    const char* name = ctx.name;
    const DenseAndSparse& b = ctx.b;
    const ProbeSet& sparse = ctx.b.sparse;
    const ProbeSampler& ss = ctx.ss;
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = ctx.b.dense.probeCount();
    stats(
        name, "stand-ins: lattice + nearest", changed, floor,
        [&](const Q& q) { return ss.sample(q.p, q.n, q.n); }, sparse.storedCount(), N);
    {
        const ProbeSampler is(b.irradianceOnly, 0);
        stats(
            name, "--free-space all: lattice + irradiance-only", changed, floor,
            [&](const Q& q) { return is.sample(q.p, q.n, q.n); }, sparse.storedCount(), N);
    }
}

// The 5 worst lookups of the L2 row (`es`: its lookup), and per absent corner of their cell its
// own tile's luminance at the normal against its L2 SH's (`l2`): where the truncation misses.
void printL2WorstLookups(const SceneContext& ctx, const ProbeSampler& es,
                         const std::function<glm::vec3(int, const glm::vec3&)>& l2) {
    const ProbeSet& dense = ctx.b.dense;
    const ProbeSet& sparse = ctx.b.sparse;
    const ProbeVolume& v = dense.volumes[0];
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::vector<std::pair<float, Q>> w = worstFirst(es, changed, floor);
    for (int k = 0; k < 5 && k < int(w.size()); ++k) {
        const Q& q = w[size_t(k)].second;
        std::printf("  L2 worst #%d rel %.3f p (%.2f %.2f %.2f) n (%g %g %g) dense %.4f "
                    "L2 %.4f; absent corners tile/L2:",
                    k, w[size_t(k)].first, q.p.x, q.p.y, q.p.z, q.n.x, q.n.y, q.n.z, q.dense,
                    pb::luminance(es.sample(q.p, q.n, q.n).irradiance));
        const glm::vec3 g = (v.toLocal(q.p) + v.halfExtents) / v.cellSize();
        glm::ivec3 base;
        for (int a = 0; a < 3; ++a)
            base[a] = std::clamp(int(std::floor(g[a])), 0, v.counts[a] - 2);
        const glm::vec3 ln = glm::transpose(v.localToWorldRotation()) * q.n;
        for (int c = 0; c < 8; ++c) {
            const int i = v.probeIndex(base + glm::ivec3(c & 1, (c >> 1) & 1, c >> 2));
            if (!fillable(sparse.states[0][size_t(i)], sparse.settings.backfaceThreshold)) continue;
            std::printf(" %.3f/%.3f", pb::luminance(tileIrradiance(dense, i, ln)),
                        pb::luminance(l2(i, ln)));
        }
        std::printf("\n");
    }
}

// 1b. Absent probes outside geometry keep an irradiance of their own (issue 18's "coarse level
//     stored everywhere"), read at their own position with visibility weight 1: the dense
//     bake's L2 SH (its ray projection), L2/L3/L4 fits of the probe's 8x8 tile, the tile
//     resampled to 4x4 and 2x2 interiors, and the tile itself (absentAsTile).
void printOwnIrradianceRows(const SceneContext& ctx) {
    const char* name = ctx.name;
    const ProbeSet& dense = ctx.b.dense;
    const ProbeSet& sparse = ctx.b.sparse;
    const auto& tris = ctx.b.tris;
    const ProbeVolume& v = dense.volumes[0];
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = dense.probeCount();
    struct Row {
        const char* label;
        AbsentIrradiance fn;
    };
    const std::vector<glm::vec3>& sh = dense.sh[0][0];
    TileFit l2fit(dense, 2), l3(dense, 3), l4(dense, 4);
    const CoarseTile t4(dense, 4), t2(dense, 2);
    // Hanning window per band (l = 0, 1, 2: 1, 0.75, 0.25): less ringing, blurrier peaks.
    auto windowed = [&](int i, const glm::vec3& d) {
        glm::vec3 c[kShL2Coefficients];
        for (int k = 0; k < kShL2Coefficients; ++k)
            c[k] = sh[std::size_t(i) * kShL2Coefficients + std::size_t(k)] * (k == 0  ? 1.0f
                                                                              : k < 4 ? 0.75f
                                                                                      : 0.25f);
        return shIrradiance(c, d, kShL2Coefficients);
    };
    // Mixed: the absent probes next to a surface corner (26-neighbourhood) keep their 8x8
    // tile, the others their L2 SH.
    const std::vector<std::uint8_t> surf = surfaceCornerProbes(v, true, tris);
    std::vector<std::uint8_t> nearSurface(surf.size(), 0);
    std::size_t nearCount = 0, absentCount = 0;
    for (int i = 0; i < v.probeCount(); ++i) {
        if (!fillable(sparse.states[0][size_t(i)], sparse.settings.backfaceThreshold)) continue;
        ++absentCount;
        const glm::ivec3 c = v.probeCoords(i);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    if (glm::all(glm::greaterThanEqual(q, glm::ivec3(0))) &&
                        glm::all(glm::lessThan(q, v.counts)) && surf[size_t(v.probeIndex(q))])
                        nearSurface[size_t(i)] = 1;
                }
        nearCount += nearSurface[size_t(i)];
    }
    std::printf("[ mixed ] %s: %zu absent probes outside geometry, %zu next to a surface "
                "corner\n",
                name, absentCount, nearCount);
    auto l2 = [&](int i, const glm::vec3& d) {
        return shIrradiance(&sh[std::size_t(i) * kShL2Coefficients], d, kShL2Coefficients);
    };
    const std::vector<Row> rows = {
        {"absent: own L2 SH, the bake's ray projection (9 coefficients)", l2},
        {"absent: own L2 SH, ray projection, Hanning-windowed", windowed},
        {"absent: 8x8 tile next to a surface corner, L2 SH (rays) elsewhere",
         [&](int i, const glm::vec3& d) {
             return nearSurface[size_t(i)] ? tileIrradiance(dense, i, d) : l2(i, d);
         }},
        {"absent: own tile fitted to band 2 (9 coefficients)", std::ref(l2fit)},
        {"absent: own tile fitted to band 3 (16 coefficients)", std::ref(l3)},
        {"absent: own tile fitted to band 4 (25 coefficients)", std::ref(l4)},
        {"absent: own tile resampled to 2x2 interior (16 texels)", t2},
        {"absent: own tile resampled to 4x4 interior (36 texels)", t4},
        {"absent: own 8x8 tile (6x6 interior, 64 texels)", nullptr},
    };
    for (const Row& row : rows) {
        const ProbeSet e = absentAsTile(dense, sparse, row.fn);
        const ProbeSampler es(e, 0);
        stats(
            name, row.label, changed, floor, [&](const Q& q) { return es.sample(q.p, q.n, q.n); },
            sparse.storedCount(), N);
        if (&row == &rows.front()) printL2WorstLookups(ctx, es, l2);
    }
}

// 2a. A lookup on the coarse lattice where the fine cell has a fillable corner.
void printCoarseLatticeRow(const SceneContext& ctx, const ProbeSampler& cs) {
    const char* name = ctx.name;
    const ProbeSet& sparse = ctx.b.sparse;
    const ProbeSampler& ss = ctx.ss;
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = ctx.b.dense.probeCount();
    stats(
        name, "coarse lattice lookup in cells with absent corners", changed, floor,
        [&](const Q& q) {
            return anyFillable(sparse, q.p) ? cs.sample(q.p, q.n, q.n) : ss.sample(q.p, q.n, q.n);
        },
        sparse.storedCount(), N);
}

// 3. Grow: keep every probe within g steps of a surface corner (with and without the coarse
// lookup in cells that still have absent corners).
// Sparse storage's kept probes plus every probe within `grow` cells of a surface corner.
std::vector<std::uint8_t> grownKeep(const ProbeVolume& v, bool root,
                                    const std::vector<pb::raytrace::WorldTriangle>& tris, int grow) {
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

void printGrowRows(const SceneContext& ctx) {
    const char* name = ctx.name;
    const ProbeSet& dense = ctx.b.dense;
    const auto& tris = ctx.b.tris;
    const ProbeVolume& v = dense.volumes[0];
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = dense.probeCount();
    for (int grow = 1; grow <= 2; ++grow) {
        const std::vector<std::uint8_t> keep = grownKeep(v, true, tris, grow);
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
}

// Reference: the coarse lattice alone everywhere (a dense step-2 volume).
void printCoarseEverywhereRow(const SceneContext& ctx, const Coarse& co, const ProbeSampler& cs) {
    const char* name = ctx.name;
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = ctx.b.dense.probeCount();
    stats(
        name, "coarse lattice everywhere (ref)", changed, floor,
        [&](const Q& q) { return cs.sample(q.p, q.n, q.n); }, co.vol.probeCount(), N);
}

// A coarse parent volume stored dense (its own bake over the lattice's points, with its
// own visibility range), read where the sparse child's cell has an absent corner; the
// child stores its surface corners and the lattice (as kept) or the surface corners only.
void printCoarseParentRows(const SceneContext& ctx, const Coarse& co) {
    const char* name = ctx.name;
    const pb::scene::Scene& scene = ctx.b.scene;
    const ProbeSet& dense = ctx.b.dense;
    const ProbeSet& sparse = ctx.b.sparse;
    const auto& tris = ctx.b.tris;
    const ProbeVolume& v = dense.volumes[0];
    const ProbeSampler& ss = ctx.ss;
    const std::vector<Q>& changed = ctx.cq.queries;
    const float floor = ctx.cq.floor;
    const std::size_t N = dense.probeCount();
    pb::studies::BakeOptions parentBake = ctx.b.bakeOptions;
    parentBake.volumes = {co.vol};
    const ProbeSet parent = pb::studies::bake(scene, parentBake);
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

// The options against the kept fill on one scene (--sh-only: up to the own-irradiance rows).
void compareOptions(const char* name, const Options& o) {
    const SceneContext ctx(name, o);
    printGridCounts(ctx);
    printWorstKeptLookups(ctx);
    printOptionsHeader();
    printStandInRows(ctx);
    printOwnIrradianceRows(ctx);
    if (o.shOnly) return;
    const Coarse co = makeCoarse(ctx.b.sparse, ctx.b.sparse.states[0]);
    const ProbeSampler cs = coarseSampler(co);
    printCoarseLatticeRow(ctx, cs);
    printGrowRows(ctx);
    printCoarseEverywhereRow(ctx, co, cs);
    printCoarseParentRows(ctx, co);
}

} // namespace

namespace {
void placementCost(const char* name) {
    pb::scene::Scene scene = pb::scene::makeBuiltinScene(name);
    AutoPlacementRequest req;
    req.sparse = true;
    req.latticeSearch = false;
    const AutoPlacementResult res = placeAutoVolumes(scene, req);
    const auto tris = pb::raytrace::staticBakeTriangles(scene);
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
    // What an irradiance of their own costs the absent probes (all of them: validity is not
    // known before the bake, so an upper bound), against the kept probes' tiles (rgba16f).
    const std::size_t absent = grid - kept;
    const std::size_t keptBytes = kept * bytesPerProbe(StorageFormat::Rgba16f).total();
    const std::size_t tileBytes = std::size_t(kIrradianceTile * kIrradianceTile) * 8;
    std::printf("[ cost ] %s absent probes %zu; kept tiles %zu B; absent L2 SH (%zu B each) "
                "+%zu B (+%.1f%%); absent 8x8 irradiance tiles (%zu B each) +%zu B (+%.1f%%)\n",
                name, absent, keptBytes, shGpuBytesPerProbe(kShL2Coefficients),
                absent * shGpuBytesPerProbe(kShL2Coefficients),
                100.0 * double(absent * shGpuBytesPerProbe(kShL2Coefficients)) / double(keptBytes),
                tileBytes, absent * tileBytes,
                100.0 * double(absent * tileBytes) / double(keptBytes));
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
void fillVariants(const char* name, const Options& o) {
    const SceneContext ctx(name, o);
    const ProbeSet& dense = ctx.b.dense;
    const auto& tris = ctx.b.tris;
    const ProbeSet& sparse = ctx.b.sparse;
    const ProbeVolume& v = dense.volumes[0];
    const ProbeSampler& ss = ctx.ss;
    const ChangedQueries& cq = ctx.cq;
    const std::vector<Q>& changed = cq.queries;
    const float floor = cq.floor;
    stats(
        name, "default: nearest", changed, floor,
        [&](const Q& q) { return ss.sample(q.p, q.n, q.n); }, sparse.storedCount(),
        dense.probeCount());
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

// The probes sparse storage leaves out outside geometry (irradiance-only under `--free-space
// all`), worst stand-in first by the bake's own score (FreeSpaceTiles.h standInErrors): (score,
// probe index).
std::vector<std::pair<float, int>> rankedLeftOutProbes(const DenseAndSparse& b) {
    const ProbeVolume& v = b.dense.volumes[0];
    const std::vector<std::vector<float>> scores =
        standInErrors(b.dense, {sparseKeptProbes(v, true, b.tris)});
    std::vector<std::pair<float, int>> ranked;
    for (int i = 0; i < v.probeCount(); ++i)
        if (b.irradianceOnly.states[0][size_t(i)].irradianceOnly)
            ranked.push_back({scores[0][size_t(i)], i});
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& c) {
        return a.first > c.first || (a.first == c.first && a.second < c.second);
    });
    return ranked;
}

// Irradiance-only tiles chosen after the bake (--slack; studies/results/
// 2026-11-29-irradiance-only-half-tiles.md): the probes sparse storage leaves out (valid,
// outside geometry) ranked by how far their stand-in's light is from their own, as the bake's
// default free space ranks them (FreeSpaceTiles.h standInErrors); the first K keep their irradiance
// tile (irradiance-only, visibility weight 1), the rest read their stand-in. Per scene: the mid-air
// lookups' mean and worst error against the dense lookup (midAirLookup(): no fade, as the test) for
// K = 0, for the K that 1%, 3% and 12% of budget slack buy (512 B per tile, slack = what the
// placement leaves of its budget), and the smallest K found (bisection) that brings the worst to <=
// 15%, with what it costs in bytes.
void slackVariants(const char* name, const Options& o) {
    const SceneContext ctx(name, o);
    const DenseAndSparse& b = ctx.b;
    const ChangedQueries& cq = ctx.cq;
    std::vector<float> dense;
    for (const Q& q : cq.queries)
        dense.push_back(pb::luminance(ctx.ds.sample(q.p, q.n, q.n, midAirLookup()).irradiance));
    const std::vector<std::pair<float, int>> ranked = rankedLeftOutProbes(b);
    struct Err {
        double mean = 0, worst = 0;
    };
    auto withTiles = [&](std::size_t k) {
        ProbeSet h = b.irradianceOnly;
        for (std::size_t r = k; r < ranked.size(); ++r) {
            ProbeState& st = h.states[0][size_t(ranked[r].second)];
            st.irradianceOnly = false;
            st.valid = false;
        }
        const ProbeSampler hs(h, 0);
        Err e;
        for (std::size_t j = 0; j < cq.queries.size(); ++j) {
            const Q& q = cq.queries[j];
            const double d =
                std::abs(pb::luminance(hs.sample(q.p, q.n, q.n, midAirLookup()).irradiance) -
                         dense[j]) /
                std::max(dense[j], cq.floor);
            e.mean += d;
            e.worst = std::max(e.worst, d);
        }
        e.mean /= double(std::max<std::size_t>(cq.queries.size(), 1));
        return e;
    };
    // As the placement's budget counts them (packed tiles and the indirection).
    const double storedBytes = double(memoryReport(b.sparse).total.storedTotal());
    const double tileBytes = double(bytesPerProbe(b.sparse.format()).irradiance);
    std::printf("[ slack ] %s: %zu stored, %zu left out outside geometry, %zu mid-air lookups "
                "changed; stored %.0f KiB\n",
                name, b.sparse.storedCount(), ranked.size(), cq.queries.size(), storedBytes / 1024);
    auto row = [&](const char* label, std::size_t k) {
        const Err e = withTiles(k);
        std::printf(
            "| %s | %s | %zu tiles (%.1f%% of the stored bytes) | mean %.4f | worst %.4f |\n", name,
            label, k, 100.0 * double(k) * tileBytes / storedBytes, e.mean, e.worst);
    };
    row("stand-ins only", 0);
    std::vector<double> slacks = {0.01, 0.03, 0.12};
    if (o.defaultPlacement) slacks.push_back(b.placementSlack);
    for (double slack : slacks) {
        char label[48];
        std::snprintf(label, sizeof label, "slack %.1f%%", 100 * slack);
        row(label,
            std::min(ranked.size(), std::size_t(storedBytes * slack / (1 - slack) / tileBytes)));
    }
    std::size_t lo = 0, hi = ranked.size();
    if (withTiles(hi).worst <= 0.15) {
        while (lo < hi) {
            const std::size_t mid = (lo + hi) / 2;
            if (withTiles(mid).worst <= 0.15)
                hi = mid;
            else
                lo = mid + 1;
        }
        row("smallest K with worst <= 15%", hi);
    }
    row("every left-out probe", ranked.size());
}

// The command line; exits with 2 on an unknown option.
Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--max-probes" && i + 1 < argc)
            o.maxProbes = std::atoi(argv[++i]);
        else if (a == "--rays" && i + 1 < argc)
            o.rays = std::atoi(argv[++i]);
        else if (a == "--sh-only")
            o.shOnly = true;
        else if (a == "--slack")
            o.slack = true;
        else if (a == "--default-placement")
            o.defaultPlacement = true;
        else if (a.rfind("--", 0) == 0) {
            std::fprintf(stderr, "bench_midair_options: unknown option %s\n", a.c_str());
            std::exit(2);
        } else
            o.scenes.push_back(a);
    }
    if (o.scenes.empty()) o.scenes = {"cornell", "rooms", "courtyard"};
    return o;
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
    try {
        for (const std::string& s : o.scenes) {
            if (o.slack) {
                slackVariants(s.c_str(), o);
                continue;
            }
            compareOptions(s.c_str(), o);
            if (!o.shOnly) fillVariants(s.c_str(), o);
            placementCost(s.c_str());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_midair_options: %s\n", e.what());
        return 1;
    }
    return 0;
}
