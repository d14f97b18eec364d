// bench_placement: does adaptive placement (`--volumes auto`, stored sparse) reach the irradiance
// error of a uniform grid with at most half of its probe memory? A benchmark, not a test
// (bench/README.md "Probe placement"): it prints a table (and JSON with --json), asserts nothing.
//
// Per scene:
//   reference  a dense bake: one uniform volume at half the default uniform spacing (8x the
//              probes), --ref-rays rays (default 128), 2 bounces, rgba16f;
//   uniform    the default uniform grid (`--volumes auto-uniform`, about 4096 probes),
//              --rays rays (default 64), 2 bounces;
//   uniform/2  a uniform grid within half of `uniform`'s memory (auto-uniform + budget);
//   adaptive dense  `--volumes auto --dense` with --probe-budget-mib = half of `uniform`'s
//              memory;
//   uniform/2 sparse, adaptive: the same two stored sparse (`--volumes auto`'s default,
//              `auto-uniform --sparse`: only probes at surface cells stored; the budget counts
//              stored tiles + the indirection).
//   --lattice-sweep adds dense uniform grids at 0.9 - 1.25x the default spacing on both
//              lattices (AutoVolume.h): "fit" puts the outer probe planes on the scene bounds
//              (auto-uniform), "pad" half a cell beyond them (auto).
// on-plane: the share of the surface lying on a probe plane (LatticeAlignment.h).
// Error: N (--points, default 20000) area-weighted random points on the static triangles
// (front side of single-sided triangles, a random side of double-sided ones), normal = view =
// the face normal, each sampled with the CPU ProbeSampler in the candidate and in the
// reference; relative error per point = sum_rgb |E - E_ref| / max(sum_rgb E_ref, 10% of the
// mean) (the floor keeps a light leak onto a nearly black point from dominating the mean);
// also nMAE = mean |E - E_ref| / mean E_ref (sums over rgb). Points sealed inside geometry (all of
// 16 hemisphere rays hit within one reference cell) and points outside the reference's volumes are
// skipped.
//
// Scenes: arguments (paths or built-in names), else the five shared scenes under
// $PB_SCENES_DIR (default ../shared/scenes: run it from the repository root).
#include "core/Error.h"
#include "probes/AutoPlacement.h"
#include "probes/Baker.h"
#include "probes/LatticeAlignment.h"
#include "probes/MemoryReport.h"
#include "probes/ProbeSampler.h"
#include "probes/RayDirections.h"
#include "probes/RayScene.h"
#include "probes/StaticTriangles.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

using namespace pb::probes;
using Clock = std::chrono::steady_clock;

struct Options {
    std::vector<std::string> scenes;
    int points = 20000, rays = 64, refRays = 128, threads = 0;
    bool json = false, latticeSweep = false;
};

struct SurfacePoint {
    glm::vec3 p, n;
};

// Area-weighted random points on the baked triangles, deterministic.
std::vector<SurfacePoint> surfacePoints(const pb::scene::Scene& s, const RayScene& rays, int count,
                                        float sealedBelow) {
    std::vector<WorldTriangle> tris = staticBakeTriangles(s);
    std::vector<double> cdf(tris.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < tris.size(); ++i)
        cdf[i] = sum += double(tris[i].area());
    const float extent = glm::length(rays.bounds().size());
    const std::vector<glm::vec3> hemi = sphericalFibonacci(32); // 16 in each hemisphere
    std::uint64_t state = 0xB0A710C5u;
    std::vector<SurfacePoint> out;
    for (int attempt = 0; attempt < count * 4 && int(out.size()) < count; ++attempt) {
        double r = double(uniformFloat(state)) * sum;
        std::size_t t = std::size_t(std::lower_bound(cdf.begin(), cdf.end(), r) - cdf.begin());
        if (t >= tris.size()) t = tris.size() - 1;
        const WorldTriangle& w = tris[t];
        float u = uniformFloat(state), v = uniformFloat(state);
        if (u + v > 1.0f) {
            u = 1.0f - u;
            v = 1.0f - v;
        }
        glm::vec3 n = w.normal;
        if (w.doubleSided && uniformFloat(state) < 0.5f) n = -n;
        glm::vec3 p = w.a + u * (w.b - w.a) + v * (w.c - w.a) + n * (1e-4f * extent);
        bool open = false;
        for (const glm::vec3& d : hemi) {
            if (glm::dot(d, n) <= 0.0f) continue;
            RayHit h = rays.intersect(p, d);
            if (!h.hit() || h.t > sealedBelow) {
                open = true;
                break;
            }
        }
        if (open) out.push_back({p, n});
    }
    return out;
}

struct Candidate {
    std::string name;
    std::vector<ProbeVolume> volumes;
    int rays = 64;
    bool sparse = false;
    ProbeSet set;
    double bakeSeconds = 0.0;
    std::vector<glm::vec3> values; // per point
    std::vector<float> weights;
};

void bake(const pb::scene::Scene& s, Candidate& c, int threads) {
    BakeRequest req;
    req.volumes = c.volumes;
    req.scenarios = resolveScenarios({}, {}, s);
    req.settings.raysPerProbe = c.rays;
    req.settings.bounces = 2;
    req.threads = threads;
    req.sparse = c.sparse;
    auto t0 = Clock::now();
    c.set = bakeProbes(s, req);
    c.bakeSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
}

void sampleAll(Candidate& c, const std::vector<SurfacePoint>& pts) {
    ProbeSampler sampler(c.set, 0);
    c.values.resize(pts.size());
    c.weights.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        IrradianceSample e = sampler.sample(pts[i].p, pts[i].n, pts[i].n);
        c.values[i] = e.irradiance;
        c.weights[i] = e.weight;
    }
}

struct Errors {
    double relative = NAN, nmae = NAN;
    std::size_t points = 0;
};

Errors errors(const Candidate& c, const Candidate& ref) {
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < ref.values.size(); ++i)
        if (ref.weights[i] > 0.99f) {
            mean += double(ref.values[i].r + ref.values[i].g + ref.values[i].b);
            ++n;
        }
    Errors out;
    if (n == 0) return out;
    mean /= double(n);
    const double floor = 0.1 * mean;
    double err = 0.0, abs = 0.0;
    for (std::size_t i = 0; i < ref.values.size(); ++i) {
        if (!(ref.weights[i] > 0.99f)) continue;
        glm::vec3 d = glm::abs(c.values[i] - ref.values[i]);
        double r = double(ref.values[i].r + ref.values[i].g + ref.values[i].b);
        err += double(d.r + d.g + d.b) / std::max(r, floor);
        abs += double(d.r + d.g + d.b);
    }
    out.points = n;
    out.relative = err / double(n);
    out.nmae = abs / double(n) / mean;
    return out;
}

std::vector<std::string> defaultScenes() {
    std::filesystem::path dir = "../shared/scenes"; // run from the repository root
    if (const char* d = std::getenv("PB_SCENES_DIR")) dir = d;
    return {(dir / "sponza_decimated/sponza_s_lod4.glb").string(),
            (dir / "cornell_box/CornellBox-Original.gltf").string(),
            (dir / "space_ship_hallway/space_ship_hallway.glb").string(),
            (dir / "japanese_bridge_garden/japanese_bridge_garden.gltf").string(),
            (dir / "dream_apartment/dream_apartment.gltf").string()};
}

nlohmann::json runScene(const std::string& path, const Options& o) {
    pb::scene::Scene s = pb::scene::loadScene(path);
    const pb::scene::Bounds bounds = staticBakeBounds(s);
    const float uniformSpacing = defaultUniformSpacing(bounds);

    Candidate ref;
    ref.name = "reference";
    ref.rays = o.refRays;
    ref.volumes.push_back(fitAutoVolume(bounds, 0.5f * uniformSpacing, 1 << 18).volume);

    AutoPlacementRequest uniformReq;
    uniformReq.mode = AutoMode::Uniform;
    Candidate uniform;
    uniform.name = "uniform";
    uniform.rays = o.rays;
    AutoPlacementResult u = placeAutoVolumes(s, uniformReq);
    uniform.volumes = u.volumes;
    const double half = 0.5 * double(u.bytes);

    Candidate uniformHalf;
    uniformHalf.name = "uniform/2";
    uniformHalf.rays = o.rays;
    uniformReq.budgetBytes = half;
    uniformHalf.volumes = placeAutoVolumes(s, uniformReq).volumes;

    AutoPlacementRequest adaptiveReq;
    adaptiveReq.budgetBytes = half;
    adaptiveReq.adaptive.threads = o.threads;
    auto t0 = Clock::now();
    AutoPlacementResult a = placeAutoVolumes(s, adaptiveReq);
    double placeSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    Candidate adaptiveDense;
    adaptiveDense.name = "adaptive dense";
    adaptiveDense.rays = o.rays;
    adaptiveDense.volumes = a.volumes;

    // The same two under the same budget, stored sparse (`--volumes auto`'s default).
    uniformReq.sparse = true;
    Candidate uniformHalfSparse;
    uniformHalfSparse.name = "uniform/2 sparse";
    uniformHalfSparse.rays = o.rays;
    uniformHalfSparse.sparse = true;
    uniformHalfSparse.volumes = placeAutoVolumes(s, uniformReq).volumes;
    adaptiveReq.sparse = true;
    Candidate adaptive;
    adaptive.name = "adaptive";
    adaptive.rays = o.rays;
    adaptive.sparse = true;
    AutoPlacementResult as = placeAutoVolumes(s, adaptiveReq);
    adaptive.volumes = as.volumes;

    // --lattice-sweep: uniform dense grids at 0.9 - 1.25x the default spacing, on the naive
    // lattice (planes on the bounds) and on auto's (half a cell beyond them).
    std::vector<Candidate> sweep;
    if (o.latticeSweep)
        for (int pad = 0; pad < 2; ++pad)
            for (float m : {0.9f, 0.95f, 1.0f, 1.05f, 1.1f, 1.15f, 1.2f, 1.25f}) {
                Candidate c;
                c.name = std::string(pad ? "pad " : "fit ") + std::to_string(m).substr(0, 4);
                c.rays = o.rays;
                c.volumes.push_back(
                    fitAutoVolume(bounds, m * uniformSpacing, 1 << 18,
                                  pad ? AutoLattice::HalfCellMargin : AutoLattice::FitBounds)
                        .volume);
                sweep.push_back(c);
            }
    RayScene rays(s);
    const glm::vec3 refCell = ref.volumes[0].cellSize();
    std::vector<SurfacePoint> pts =
        surfacePoints(s, rays, o.points, std::min(refCell.x, std::min(refCell.y, refCell.z)));

    nlohmann::json rows = nlohmann::json::array();
    std::vector<Candidate*> all{&ref,           &uniform,           &uniformHalf,
                                &adaptiveDense, &uniformHalfSparse, &adaptive};
    for (Candidate& c : sweep)
        all.push_back(&c);
    const std::vector<WorldTriangle> tris = staticBakeTriangles(s);
    for (Candidate* c : all) {
        bake(s, *c, o.threads);
        sampleAll(*c, pts);
    }
    for (Candidate* c : all) {
        MemoryReport m = memoryReport(c->set);
        Errors err = c == &ref ? Errors{0.0, 0.0, 0} : errors(*c, ref);
        glm::vec3 cell = c->volumes.back().cellSize();
        float onPlane = 0.0f;
        for (const ProbeVolume& v : c->volumes)
            onPlane = std::max(onPlane, surfaceOnProbePlanes(v, tris));
        rows.push_back({{"placement", c->name},
                        {"on_plane", onPlane},
                        {"volumes", c->volumes.size()},
                        {"probes", m.total.probes},
                        {"stored_probes", m.total.storedProbes},
                        {"mib", double(m.total.storedTotal()) / (1024.0 * 1024.0)},
                        {"finest_spacing", std::max(cell.x, std::max(cell.y, cell.z))},
                        {"far_probes", m.total.sparse.far},
                        {"rays", c->rays},
                        {"mean_relative_error", err.relative},
                        {"nmae", err.nmae},
                        {"points", err.points},
                        {"bake_s", c->bakeSeconds}});
    }
    return {{"scene", s.name},
            {"points_requested", o.points},
            {"points_on_surfaces", pts.size()},
            {"adaptive_dense_place_s", placeSeconds},
            {"adaptive_dense_notes", a.notes},
            {"adaptive_notes", as.notes},
            {"rows", rows}};
}

void printTable(const nlohmann::json& r) {
    std::printf("\n%s: %zu surface points (adaptive dense placement %.2f s)\n",
                r["scene"].get<std::string>().c_str(), r["points_on_surfaces"].get<std::size_t>(),
                r["adaptive_dense_place_s"].get<double>());
    std::printf("  %-16s %7s %8s %8s %9s %8s %8s %5s %9s %7s %8s %8s\n", "placement", "volumes",
                "probes", "stored", "MiB", "finest", "far", "rays", "mean err", "nMAE", "bake s",
                "on-plane");
    for (const auto& row : r["rows"])
        std::printf("  %-16s %7zu %8zu %8zu %9.2f %8.3f %8zu %5d %9.4f %7.4f %8.2f %8.4f\n",
                    row["placement"].get<std::string>().c_str(), row["volumes"].get<std::size_t>(),
                    row["probes"].get<std::size_t>(), row["stored_probes"].get<std::size_t>(),
                    row["mib"].get<double>(), row["finest_spacing"].get<double>(),
                    row["far_probes"].get<std::size_t>(), row["rays"].get<int>(),
                    row["mean_relative_error"].get<double>(), row["nmae"].get<double>(),
                    row["bake_s"].get<double>(), row["on_plane"].get<double>());
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw pb::Error(a + ": needs a value");
            return argv[++i];
        };
        try {
            if (a == "--points")
                o.points = std::stoi(next());
            else if (a == "--rays")
                o.rays = std::stoi(next());
            else if (a == "--ref-rays")
                o.refRays = std::stoi(next());
            else if (a == "--threads")
                o.threads = std::stoi(next());
            else if (a == "--json")
                o.json = true;
            else if (a == "--lattice-sweep")
                o.latticeSweep = true;
            else if (a.rfind("--", 0) == 0)
                throw pb::Error(a + ": unknown option (--points N, "
                                    "--rays N, --ref-rays N, "
                                    "--threads N, --json, --lattice-sweep)");
            else
                o.scenes.push_back(a);
        } catch (const std::logic_error&) {
            std::cerr << "bench_placement: " << a << ": expects an integer\n";
            return 2;
        } catch (const pb::Error& e) {
            std::cerr << "bench_placement: " << e.what() << "\n";
            return 2;
        }
    }
    if (o.scenes.empty()) o.scenes = defaultScenes();
    nlohmann::json all = nlohmann::json::array();
    for (const std::string& scene : o.scenes) {
        try {
            nlohmann::json r = runScene(scene, o);
            if (!o.json) printTable(r);
            all.push_back(r);
        } catch (const pb::Error& e) {
            std::cerr << "bench_placement: " << scene << ": " << e.what() << "\n";
            return 1;
        }
    }
    if (o.json) std::cout << all.dump(2) << "\n";
    return 0;
}
