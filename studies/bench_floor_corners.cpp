// bench_floor_corners: why does a uniform grid print rings on a floor? (issue 24) A diagnostic,
// not a test: it prints tables, asserts nothing (studies/findings/lattice-on-floors.md "Lattice on floors").
//
// The floor lines of bench_lattice (same finder, seed and spacing; --below Y for one storey) are
// looked up in the `--volumes auto-uniform` grid, baked as bench_lattice bakes it (2 bounces,
// --rays, one round), and compared with the same gathered truth. For every point the lookup's
// 8 corners are recomputed term by term with RTXGI's formulas as the sampler had them before
// the behind-surface fade (ProbeSampler.cpp steps 3-4): trilinear weight, wrap (backface)
// weight, the visibility texel's mean and mean^2 against the biased point's distance, the
// Chebyshev weight, whether the crush applied, and the corner's own irradiance towards the
// normal over the truth. The variants table re-weights the same corners with terms left out
// or changed (the candidates tried; "plane .2 cell" is the sampler now, and the tool checks
// it against ProbeSampler point by point). Points are binned by their horizontal distance to
// the nearest probe column (0: under a probe, 0.71: the middle of a cell, in cells); `lookup`
// and `rel err` there are the sampler's, the per-plane terms RTXGI's.
//
// --patch X0 Z0 ROWS replaces the lines with ROWS rows of 64 points along X from (X0, Z0), the
// same step apart in Z (a patch of the floor seen from --below; rows that leave it are dropped).
// --dump FILE writes every point's terms (CSV).
// Usage: bench_floor_corners [--rays R] [--gather-rays G] [--lines N] [--below Y]
//                            [--patch X0 Z0 ROWS] [--dump FILE] [SCENE]  (default: Sponza, --below
//                            1)
#include "core/Error.h"
#include "core/Luminance.h"
#include "core/ReuseFreedMemory.h"
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"
#include "probes/ProbeSampler.h"
#include "raytrace/RayScene.h"
#include "probes/bake/SurfaceGather.h"
#include "probes/placement/AutoPlacement.h"
#include "scene/SceneLoader.h"
#include "studies/common/LatticeScore.h"
#include "studies/common/SharedScenes.h"
#include "studies/common/StudyBake.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace pb;
using namespace pb::probes;
using studies::FloorLine;

namespace {

constexpr int kSamplesPerLine = 64, kSamplesPerCell = 8, kBins = 6;

// A bake of one round (--noise-target 0), as bench_lattice bakes.
ProbeSet bakeOneRound(const scene::Scene& s, const std::vector<ProbeVolume>& volumes, int rays,
                      int bounces) {
    studies::BakeOptions b;
    b.volumes = volumes;
    b.rays = rays;
    b.bounces = bounces;
    b.noiseTarget = 0.0f;
    return studies::bake(s, b);
}

// One corner's terms, as ProbeSampler::finish computes them.
struct Corner {
    bool live = false;
    int layer = 0; // j of the probe
    float tri = 0, wrap = 0, mean = 0, meanSq = 0, d01 = 0, cheb = 1, w = 0;
    bool crushed = false;
    bool front = true; // the probe is on the normal's side of the surface
    float cos = 1;     // dot(direction to the probe, n), t = (cos + 1) / 2
    float height = 0;  // dot(probe - p, n): the probe's height over the surface's plane
    float lum = 0;     // the corner's irradiance towards the normal (luminance)
    glm::vec3 probe{0};
};

// The lookup with some of its terms left out or changed, to attribute the error and to try
// candidate fixes: see kVariantNames (the last ones are the candidates for probes behind the
// surface, dot(probe - p, n) < 0).
constexpr int kVariants = 15;
constexpr int kSamplerVariant = 12; // what ProbeSampler computes now (checked per point)
const char* const kVariantNames[kVariants] = {
    "tri", "tri*wrap", "tri*cheb", "no crush", "RTXGI (before)",
    "front only",        // behind probes dropped when a probe in front contributes
    "wrap no bias",      // wrap t^2 without the +0.2 for every probe
    "ramp .2 floor .05", // wrap x max(clamp(1 + cos / 0.2, 0, 1), 0.05), before the crush
    "ramp .2 floor .01", // the same, floor 0.01
    "ramp .1 floor .05", // ramp over cos in [-0.1, 0]
    "ramp .3 floor .05",
    "ramp .2 .05 after crush", // the factor applied after the crush
    "plane .2 cell", // after the crush: max(clamp(1 + dot(probe - p, n) / (0.2 minCell)), 0.05):
                     // the sampler since this tool was written (kBehindRampCells)
    "plane .1 cell", "plane .3 cell"};

struct Lookup {
    Corner c[8];
    float lum = 0; // normalised
    float variant[kVariants] = {};
};

// The lookup of every variant (kVariantNames) from the same corners: their weights with
// terms left out or changed, over the corners' irradiance.
void reweightVariants(Lookup& out, float minCell) {
    const auto crush = [](float w) {
        return w < kCrushThreshold ? w * w * w / (kCrushThreshold * kCrushThreshold) : w;
    };
    bool anyFront = false;
    for (const Corner& c : out.c)
        anyFront |= c.live && c.front && c.w > 0;
    for (int var = 0; var < kVariants; ++var) {
        float vw = 0, vl = 0;
        for (const Corner& c : out.c) {
            if (!c.live || (var == 5 && anyFront && !c.front)) continue;
            const float tri = std::max(c.tri, kMinTrilinear);
            const float t = (c.cos + 1) * 0.5f;
            float w = 0;
            switch (var) {
            case 0:
                w = tri;
                break;
            case 1:
                w = tri * c.wrap;
                break;
            case 2:
                w = tri * c.cheb;
                break;
            case 3:
                w = tri * c.wrap * c.cheb;
                break;
            case 6:
                w = tri * crush(t * t * c.cheb);
                break;
            case 7:
            case 8:
            case 9:
            case 10: {
                const float width = var == 9 ? 0.1f : var == 10 ? 0.3f : 0.2f;
                const float floorS = var == 8 ? 0.01f : 0.05f;
                const float ramp = std::max(std::clamp(1 + c.cos / width, 0.0f, 1.0f), floorS);
                w = tri * crush(c.wrap * ramp * c.cheb);
                break;
            }
            case 11: {
                const float ramp = std::max(std::clamp(1 + c.cos / 0.2f, 0.0f, 1.0f), 0.05f);
                w = tri * crush(c.wrap * c.cheb) * ramp;
                break;
            }
            case 12:
            case 13:
            case 14: {
                const float width = (var == 12 ? 0.2f : var == 13 ? 0.1f : 0.3f) * minCell;
                const float ramp = std::max(std::clamp(1 + c.height / width, 0.0f, 1.0f), 0.05f);
                w = tri * crush(c.wrap * c.cheb) * ramp;
                break;
            }
            default:
                w = c.w;
                break;
            }
            vw += w;
            vl += w * c.lum;
        }
        out.variant[var] = vw > 0 ? vl / vw : 0;
    }
}

// The lookup at `world` with normal (= view) `nWorld` in volume `vi` of `set`, term by term:
// each of the 8 corners as RTXGI computes it, then every variant (reweightVariants).
Lookup corners(const ProbeSet& set, int vi, const glm::vec3& world, const glm::vec3& nWorld) {
    const ProbeVolume& v = set.volumes[std::size_t(vi)];
    const glm::mat3 toLocal = glm::transpose(v.localToWorldRotation());
    const glm::vec3 p = toLocal * (world - v.center);
    const glm::vec3 n = glm::normalize(toLocal * nWorld);
    const glm::vec3 biased = p + kBiasNormalWeight * n * (kBiasScale * v.minCellSize());
    const glm::vec3 cell = v.cellSize();
    glm::ivec3 base(0);
    glm::vec3 alpha(0);
    for (int a = 0; a < 3; ++a) {
        if (v.counts[a] <= 1) continue;
        float g = std::clamp((p[a] + v.halfExtents[a]) / cell[a], 0.0f, float(v.counts[a] - 2));
        base[a] = int(std::floor(g));
        alpha[a] = std::clamp((biased[a] + v.halfExtents[a]) / cell[a] - float(base[a]), 0.f, 1.f);
    }
    Lookup out;
    float sumW = 0, sumL = 0;
    const auto& states = set.states[std::size_t(vi)];
    for (int i = 0; i < 8; ++i) {
        Corner& c = out.c[i];
        const glm::ivec3 g = base + glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        if (g.x >= v.counts.x || g.y >= v.counts.y || g.z >= v.counts.z) continue;
        const ProbeState& st = states[std::size_t(v.probeIndex(g))];
        c.live = st.valid;
        c.layer = g.y;
        c.probe = v.gridLocal(g) + st.offset;
        const glm::vec3 toPoint = biased - c.probe;
        const float dist = glm::length(toPoint);
        const glm::vec3 dir = dist > 0 ? toPoint / dist : n;
        float vis[2], irr[4];
        const glm::vec2 vc = tileCoord(g, dir, kVisibilityInterior);
        bilinearFetch(set.visibility[std::size_t(vi)], vc.x, vc.y, g.y, vis);
        const glm::vec2 ic = tileCoord(g, n, kIrradianceInterior);
        bilinearFetch(set.irradiance[0][std::size_t(vi)], ic.x, ic.y, g.y, irr);
        c.lum = pb::luminance({irr[0], irr[1], irr[2]});
        const glm::vec3 q = c.probe - p;
        const glm::vec3 toProbe = glm::length(q) > 0 ? glm::normalize(q) : n;
        const float t = (glm::dot(toProbe, n) + 1.0f) * 0.5f;
        c.wrap = t * t + kWrapBias;
        c.front = glm::dot(q, n) > 0.0f;
        c.cos = glm::dot(toProbe, n);
        c.height = glm::dot(q, n);
        c.mean = vis[0];
        c.meanSq = vis[1];
        c.d01 = dist / v.maxDistance();
        const float variance = std::max(c.meanSq - c.mean * c.mean, kVarianceFloor);
        const float dd = c.d01 - c.mean;
        const float ch = variance / (variance + dd * dd);
        c.cheb = c.d01 > c.mean ? std::max(ch * ch * ch, kChebyshevFloor) : 1.0f;
        float w = c.wrap * c.cheb;
        c.crushed = w < kCrushThreshold;
        if (c.crushed) w = w * w * w / (kCrushThreshold * kCrushThreshold);
        c.tri = ((i & 1) ? alpha.x : 1 - alpha.x) * ((i & 2) ? alpha.y : 1 - alpha.y) *
                ((i & 4) ? alpha.z : 1 - alpha.z);
        c.w = w * std::max(c.tri, kMinTrilinear);
        if (!c.live) continue;
        sumW += c.w;
        sumL += c.w * c.lum;
    }
    out.lum = sumW > 0 ? sumL / sumW : 0;
    reweightVariants(out, v.minCellSize());
    return out;
}

struct Bin {
    int points = 0;
    double truth = 0, lookup = 0, sq = 0;
    // per plane (0: the plane below the biased point, 1: above): weight share, mean terms
    double share[2] = {}, wrap[2] = {}, cheb[2] = {}, crushed[2] = {}, tri[2] = {}, ratio[2] = {},
           d01[2] = {}, mean[2] = {}, sigma[2] = {}, height[2] = {};
    int n[2] = {};
};

// The command line (usage above).
struct Options {
    int rays = 64, gatherRays = 256, lineCount = 40;
    float below = 1.0f;
    std::string scenePath, dumpPath;
    glm::vec2 patch{0.0f}; // --patch X0 Z0 ROWS: the patch's corner and its rows
    int patchRows = 0;
};

// The points looked up: lines of kSamplesPerLine points, and the points line after line.
struct FloorPoints {
    std::vector<FloorLine> lines;
    std::vector<GatherPoint> points;
};

// What the points add up to: per bin of distance to the nearest probe column the sampler's and
// the corners' terms, per variant the squared error and each line's residual, and how far the
// recomputed sampler variant is from ProbeSampler.
struct Analysis {
    Bin bins[kBins];
    double worstCheck = 0;
    double varSq[kVariants] = {}, truthSum = 0;
    std::vector<std::vector<double>> varResidual; // variant-major: [variant * lines + line]
};

// The command line; exits with 2 on an unknown option.
Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--rays" && more)
            o.rays = std::atoi(argv[++i]);
        else if (a == "--gather-rays" && more)
            o.gatherRays = std::atoi(argv[++i]);
        else if (a == "--lines" && more)
            o.lineCount = std::atoi(argv[++i]);
        else if (a == "--patch" && i + 3 < argc) {
            o.patch = {float(std::atof(argv[i + 1])), float(std::atof(argv[i + 2]))};
            o.patchRows = std::atoi(argv[i + 3]);
            i += 3;
        } else if (a == "--dump" && more)
            o.dumpPath = argv[++i];
        else if (a == "--below" && more)
            o.below = float(std::atof(argv[++i]));
        else if (a.rfind("--", 0) == 0) {
            std::fprintf(stderr, "bench_floor_corners: error: %s: unknown option\n", a.c_str());
            std::exit(2);
        } else
            o.scenePath = a;
    }
    if (o.scenePath.empty()) o.scenePath = studies::sharedScenes()[0];
    return o;
}

// --patch: rows along X, `step` apart in Z, each point dropped onto the floor from --below
// (rows with a miss or a non-upward hit are skipped).
FloorPoints patchRows(const pb::raytrace::RayScene& rs, const Options& o, float step) {
    FloorPoints fp;
    for (int row = 0; row < o.patchRows; ++row) {
        std::vector<GatherPoint> rowPoints;
        for (int i = 0; i < kSamplesPerLine; ++i) {
            const glm::vec3 p(o.patch.x + step * float(i), o.below, o.patch.y + step * float(row));
            const pb::raytrace::RayHit h = rs.intersect(p, {0, -1, 0});
            if (!h.hit() || std::abs(rs.faceNormal(h.geomID, h.primID).y) < 0.9f) {
                std::fprintf(stderr, "row %d dropped at x %.2f (no flat floor)\n", row, p.x);
                break;
            }
            rowPoints.push_back({p + glm::vec3(0, -h.t, 0), {0, 1, 0}});
        }
        if (rowPoints.size() != std::size_t(kSamplesPerLine)) continue;
        fp.lines.push_back({rowPoints[0].pos, {1, 0, 0}, step, kSamplesPerLine});
        fp.points.insert(fp.points.end(), rowPoints.begin(), rowPoints.end());
    }
    return fp;
}

// bench_lattice's floor lines (same finder, seed and step; --lines, --below).
FloorPoints floorLines(const pb::raytrace::RayScene& rs, const Options& o, float step) {
    FloorPoints fp;
    fp.lines =
        studies::findFloorLines(rs, o.lineCount, kSamplesPerLine, step, 0x11A77ECEu, o.below);
    for (const FloorLine& l : fp.lines)
        for (int i = 0; i < l.samples; ++i)
            fp.points.push_back({l.point(i), {0, 1, 0}});
    return fp;
}

// The truth at the points: the last bounce gathered there, the first from a 1-bounce bake of
// the uniform grid.
std::vector<glm::vec3> gatherTruth(const scene::Scene& s, const pb::raytrace::RayScene& rs,
                                   const std::vector<ProbeVolume>& uniform, const FloorPoints& fp,
                                   const Options& o) {
    const ProbeSet first = bakeOneRound(s, uniform, o.rays, 1);
    const ProbeSampler indirect(first, 0);
    GatherSettings gs;
    gs.rays = o.gatherRays;
    return gatherIrradiance(rs, resolveScenarios({}, {}, s)[0], s.lights, fp.points, &indirect, gs);
}

void printVolume(const FloorPoints& fp, const ProbeVolume& v0) {
    std::printf("%zu lines, %zu points; volume 0: counts %d %d %d, cell %.3f %.3f %.3f, "
                "maxDistance %.3f, bias %.3f\n",
                fp.lines.size(), fp.points.size(), v0.counts.x, v0.counts.y, v0.counts.z,
                v0.cellSize().x, v0.cellSize().y, v0.cellSize().z, v0.maxDistance(),
                kBiasScale * v0.minCellSize());
}

void writeDumpHeader(std::FILE* dump) {
    std::fprintf(dump, "line,i,x,y,z,r,truth,lookup,tri,triwrap,tricheb,nocrush"
                       ",w0,w1,w2,w3,wrap0,wrap1,wrap2,wrap3,cheb0,cheb1,cheb2,cheb3"
                       ",e0,e1,e2,e3\n");
}

// One point's CSV row (--dump): the first four variants and the upper corners' terms.
void dumpPoint(std::FILE* dump, std::size_t k, const glm::vec3& p, float r, double t, float mine,
               const Lookup& l) {
    std::fprintf(dump, "%zu,%zu,%.4f,%.4f,%.4f,%.3f,%.5f,%.5f", k / kSamplesPerLine,
                 k % kSamplesPerLine, p.x, p.y, p.z, r, t, mine);
    for (int var = 0; var < 4; ++var)
        std::fprintf(dump, ",%.5f", l.variant[var]);
    const int up[4] = {2, 3, 6, 7};
    for (int q : up)
        std::fprintf(dump, ",%.4f", l.c[q].w);
    for (int q : up)
        std::fprintf(dump, ",%.4f", l.c[q].wrap);
    for (int q : up)
        std::fprintf(dump, ",%.4f", l.c[q].cheb);
    for (int q : up)
        std::fprintf(dump, ",%.5f", l.c[q].lum);
    std::fprintf(dump, "\n");
}

// A point's lookup and its corners' terms into its bin, per plane of corners.
void addToBin(Bin& b, const Lookup& l, const glm::vec3& local, double t, float mine) {
    ++b.points;
    b.truth += t;
    b.lookup += mine;
    b.sq += (mine - t) * (mine - t);
    float sumW = 0;
    for (const Corner& c : l.c)
        sumW += c.live ? c.w : 0;
    const int lowLayer = l.c[0].layer;
    for (const Corner& c : l.c) {
        if (!c.live) continue;
        const int plane = c.layer == lowLayer ? 0 : 1;
        b.n[plane]++;
        b.share[plane] += c.w / sumW;
        b.wrap[plane] += c.wrap;
        b.cheb[plane] += c.cheb;
        b.crushed[plane] += c.crushed;
        b.tri[plane] += c.tri;
        b.ratio[plane] += c.lum / t;
        b.d01[plane] += c.d01;
        b.mean[plane] += c.mean;
        b.sigma[plane] += std::sqrt(std::max(c.meanSq - c.mean * c.mean, 0.0f));
        b.height[plane] += c.probe.y - local.y;
    }
}

// Every point looked up in `set`: its corners recomputed (corners()), checked against the
// sampler, binned by its horizontal distance to the nearest probe column; --dump writes it.
Analysis analysePoints(const ProbeSet& set, const ProbeSampler& sampler, const FloorPoints& fp,
                       const std::vector<glm::vec3>& truth, std::FILE* dump) {
    Analysis a;
    a.varResidual.resize(kVariants * fp.lines.size());
    for (std::size_t k = 0; k < fp.points.size(); ++k) {
        const glm::vec3 p = fp.points[k].pos;
        const int vi = sampler.selectVolume(p);
        if (vi < 0) continue;
        const IrradianceSample ref = sampler.sample(p, {0, 1, 0}, {0, 1, 0});
        const Lookup l = corners(set, vi, p, {0, 1, 0});
        const float refL = pb::luminance(ref.irradiance);
        const float mine = l.variant[kSamplerVariant];
        a.worstCheck =
            std::max(a.worstCheck, double(std::abs(refL - mine) / std::max(refL, 1e-6f)));
        const ProbeVolume& v = set.volumes[std::size_t(vi)];
        const glm::vec3 local = v.toLocal(p);
        const glm::vec3 cell = v.cellSize();
        // Horizontal distance (cells) to the nearest lattice column.
        const float fx = (local.x + v.halfExtents.x) / cell.x,
                    fz = (local.z + v.halfExtents.z) / cell.z;
        const float dx = fx - std::round(fx), dz = fz - std::round(fz);
        const float r = std::sqrt(dx * dx + dz * dz);
        Bin& b = a.bins[std::min(kBins - 1, int(r / 0.7072f * kBins))];
        const double t = pb::luminance(truth[k]);
        const std::size_t line = k / kSamplesPerLine;
        a.truthSum += t;
        for (int var = 0; var < kVariants; ++var) {
            a.varSq[var] += (l.variant[var] - t) * (l.variant[var] - t);
            a.varResidual[std::size_t(var) * fp.lines.size() + line].push_back(l.variant[var] - t);
        }
        if (dump) dumpPoint(dump, k, p, r, t, mine, l);
        addToBin(b, l, local, t, mine);
    }
    return a;
}

// Per variant the relative RMS error and the median lattice score of the full lines.
void printVariants(const Analysis& a, const FloorPoints& fp, const ProbeVolume& v0) {
    const double meanTruth = a.truthSum / double(fp.points.size());
    std::printf("variant           rel RMS  score median  (lines: residual / line's mean truth)\n");
    for (int var = 0; var < kVariants; ++var) {
        std::vector<double> scores;
        for (std::size_t li = 0; li < fp.lines.size(); ++li) {
            const std::vector<double>& res = a.varResidual[std::size_t(var) * fp.lines.size() + li];
            if (res.size() != std::size_t(kSamplesPerLine)) continue;
            const float sp = fp.lines[li].axis.x != 0.0f ? v0.cellSize().x : v0.cellSize().z;
            scores.push_back(studies::latticeScore(res, fp.lines[li].step, 1.0f / sp));
        }
        std::sort(scores.begin(), scores.end());
        std::printf("%-15s %9.4f %13.2f\n", kVariantNames[var],
                    std::sqrt(a.varSq[var] / double(fp.points.size())) / meanTruth,
                    scores.empty() ? 0.0 : scores[scores.size() / 2]);
    }
    std::printf("'%s' recomputed vs the sampler: worst relative difference %.2e\n",
                kVariantNames[kSamplerVariant], a.worstCheck);
}

// Per bin of distance to the nearest probe column: the lookup over the truth, its error, and
// per plane of corners (lower, upper) their mean terms.
void printBins(const Analysis& a) {
    std::printf("%-11s %6s %7s %7s | %-5s %6s %5s %6s %6s %6s %6s %6s %6s %6s\n", "r (cells)",
                "points", "lookup", "rel err", "plane", "share", "tri", "wrap", "cheb", "crush",
                "d01", "mean", "sigma", "E/truth");
    for (int i = 0; i < kBins; ++i) {
        const Bin& b = a.bins[i];
        if (!b.points) continue;
        for (int pl = 0; pl < 2; ++pl) {
            const double m = std::max(b.n[pl], 1);
            char head[64] = "";
            if (pl == 0)
                std::snprintf(head, sizeof(head), "%.2f-%.2f", 0.7072 * i / kBins,
                              0.7072 * (i + 1) / kBins);
            if (pl == 0)
                std::printf("%-11s %6d %7.3f %+7.3f", head, b.points, b.lookup / b.truth,
                            std::sqrt(b.sq / b.points) / (b.truth / b.points));
            else
                std::printf("%-11s %6s %7s %7s", "", "", "", "");
            std::printf(" | %-5s %6.3f %5.3f %6.3f %6.3f %6.2f %6.3f %6.3f %6.3f %6.3f  h=%.3f\n",
                        pl ? "upper" : "lower", b.share[pl] / b.points, b.tri[pl] / m,
                        b.wrap[pl] / m, b.cheb[pl] / m, b.crushed[pl] / m, b.d01[pl] / m,
                        b.mean[pl] / m, b.sigma[pl] / m, b.ratio[pl] / m, b.height[pl] / m);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
    try {
        const scene::Scene s = scene::loadScene(o.scenePath);
        const pb::raytrace::RayScene rs(s);
        AutoPlacementRequest req;
        req.mode = AutoMode::Uniform;
        const std::vector<ProbeVolume> uniform = placeAutoVolumes(s, req).volumes;
        const float step = uniform[0].cellSize().x / kSamplesPerCell;
        const FloorPoints fp = o.patchRows > 0 ? patchRows(rs, o, step) : floorLines(rs, o, step);
        const std::vector<glm::vec3> truth = gatherTruth(s, rs, uniform, fp, o);
        const ProbeSet set = bakeOneRound(s, uniform, o.rays, 2);
        const ProbeSampler sampler(set, 0);
        printVolume(fp, set.volumes[0]);
        std::FILE* dump = o.dumpPath.empty() ? nullptr : std::fopen(o.dumpPath.c_str(), "w");
        if (dump) writeDumpHeader(dump);
        const Analysis a = analysePoints(set, sampler, fp, truth, dump);
        if (dump) std::fclose(dump);
        printVariants(a, fp, set.volumes[0]);
        printBins(a);
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_floor_corners: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
