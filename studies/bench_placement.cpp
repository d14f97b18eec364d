// bench_placement: does adaptive placement (`--volumes auto`, stored sparse) reach the irradiance
// error of a uniform grid with at most half of its probe memory? A benchmark, not a test
// (studies/findings/probe-placement.md "Probe placement"): it prints a table (and JSON with --json), asserts nothing.
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
//              stored tiles + the indirection), with `bake`'s default free space (ranked: the
//              placement leaves 5% of the budget to the irradiance tiles of the left-out probes
//              whose stand-ins are furthest off, FreeSpaceTiles.h).
//   adaptive unshifted  `adaptive` without its measured lattice search
//              (`--no-lattice-search`, LatticeShiftSearch.h): what the search bought. The
//              search scores shifts on its own surface samples (another seed), never on these.
//   --lattice-sweep adds dense uniform grids at 0.9 - 1.25x the default spacing on both
//              lattices (AutoVolume.h): "fit" puts the outer probe planes on the scene bounds
//              (auto-uniform), "pad" half a cell beyond them (auto).
// on-plane: the share of the surface lying on a probe plane (LatticeAlignment.h).
// Error: N (--points, default 20000) area-weighted random points on the static triangles
// (front side of single-sided triangles, a random side of double-sided ones), normal = view =
// the face normal, each sampled with the CPU ProbeSampler in every candidate. The truth E_ref
// at a point is gathered there directly (SurfaceGather.h, --gather-rays rays, default 512): the
// last of the 2 bounces exact, the first read from a 1-bounce bake of the reference grid at
// the hits. A probe grid as the reference would share the candidates' own probe artefacts
// (leaks, self-shadowing, the lattice's planes), so it is only reported beside it:
// "grid err" is the same error against the reference grid above.
// Relative error per point = sum_rgb |E - E_ref| / max(sum_rgb E_ref, 10% of the mean) (the
// floor keeps a light leak onto a nearly black point from dominating the mean); also
// nMAE = mean |E - E_ref| / mean E_ref (sums over rgb). Points sealed inside geometry (all of
// 16 hemisphere rays hit within one reference cell) and points outside the reference grid's
// volumes are skipped.
//
// Mid-air (issue 18): --mid-air-points (default 2000) points in the free space of the
// reference grid's volume (MidAirSamples.h: not inside geometry nor sealed within one
// reference cell, as the surface points), each looked up with the six
// axis normals and scored against a gather over the whole sphere at the point
// (gatherIrradianceSphere, --gather-rays rays, the first bounce from the same 1-bounce
// reference bake): "air err", the same relative error as "mean err", every lookup counted (an
// unlit one as E = 0; "unlit" counts them).
//
// Scenes: arguments (paths or built-in names), else the five shared scenes under
// $PB_SCENES_DIR (default ../shared/scenes: run it from the repository root).
#include "core/Error.h"
#include "core/ReuseFreedMemory.h"
#include "probes/ProbeSampler.h"
#include "raytrace/StaticTriangles.h"
#include "probes/bake/MidAirSamples.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "probes/bake/SurfaceGather.h"
#include "probes/bake/SurfaceSamples.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/placement/IrradianceError.h"
#include "probes/placement/LatticeAlignment.h"
#include "probes/store/MemoryReport.h"
#include "scene/SceneLoader.h"
#include "studies/common/SharedScenes.h"
#include "studies/common/StudyBake.h"

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

// The command line (usage above).
struct Options {
    std::vector<std::string> scenes;
    int points = 20000, rays = 64, refRays = 128, gatherRays = 512, threads = 0;
    int midAirPoints = 2000; // x 6 normals

    bool json = false, latticeSweep = false;
};

struct Candidate {
    std::string name;
    std::vector<ProbeVolume> volumes;
    int rays = 64, bounces = 2;
    bool sparse = false;
    double budget = 0.0; // sparse: what the free-space tiles fill (FreeSpace::Ranked)
    ProbeSet set;
    double bakeSeconds = 0.0;
    std::vector<glm::vec3> values; // per point
    std::vector<float> weights;
    std::vector<glm::vec3> midAirValues; // per mid-air point and axis normal
    std::vector<float> midAirWeights;
};

// The placements one scene compares (usage above), and what the adaptive placements reported.
struct Candidates {
    Candidate ref, uniform, uniformHalf, adaptiveDense, uniformHalfSparse, asPlaced, adaptive;
    std::vector<Candidate> sweep; // --lattice-sweep
    AutoPlacementResult adaptiveDensePlacement, adaptivePlacement;
    double adaptiveDensePlaceSeconds = 0.0;

    // Every candidate in the table's order (the reference first).
    std::vector<Candidate*> all() {
        std::vector<Candidate*> out{
            &ref, &uniform, &uniformHalf, &adaptiveDense, &uniformHalfSparse, &asPlaced, &adaptive};
        for (Candidate& c : sweep)
            out.push_back(&c);
        return out;
    }
};

// Where the candidates are scored, and the truth there: surface points (a gather over the
// hemisphere) and mid-air points (a gather over the sphere, per axis normal); the first
// bounce of both from a 1-bounce bake of the reference grid.
struct Truth {
    std::vector<pb::raytrace::WorldTriangle> tris; // the static triangles (on-plane shares)
    std::vector<GatherPoint> points;
    std::vector<glm::vec3> surface;
    double gatherSeconds = 0.0;
    std::vector<glm::vec3> midAir, midAirTruth;
    double midAirGatherSeconds = 0.0;
    double firstBounceBakeSeconds = 0.0;
};

// A dynamic object's sides: the mid-air points are looked up (and gathered) with each.
const std::vector<glm::vec3> kAxes = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

// Bakes the candidate (sparse ones with `bake`'s default free space: Ranked tiles within its
// budget) and times the bake.
void bakeCandidate(const pb::scene::Scene& s, Candidate& c, int threads) {
    pb::studies::BakeOptions b;
    b.volumes = c.volumes;
    b.rays = c.rays;
    b.bounces = c.bounces;
    b.threads = threads;
    b.sparse = c.sparse;
    b.freeSpace = c.sparse ? FreeSpace::Ranked : FreeSpace::StandIns;
    b.freeSpaceBudgetBytes = c.budget;
    auto t0 = Clock::now();
    c.set = pb::studies::bake(s, b);
    c.bakeSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
}

void sampleAll(Candidate& c, const std::vector<GatherPoint>& pts,
               const std::vector<glm::vec3>& midAir) {
    ProbeSampler sampler(c.set, 0);
    c.midAirValues.clear();
    c.midAirWeights.clear();
    for (const glm::vec3& p : midAir)
        for (const glm::vec3& n : kAxes) {
            const IrradianceSample e = sampler.sample(p, n, n, midAirLookup());
            c.midAirValues.push_back(e.irradiance);
            c.midAirWeights.push_back(e.weight);
        }
    c.values.resize(pts.size());
    c.weights.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        IrradianceSample e = sampler.sample(pts[i].pos, pts[i].normal, pts[i].normal);
        c.values[i] = e.irradiance;
        c.weights[i] = e.weight;
    }
}

Candidate candidate(const std::string& name, int rays) {
    Candidate c;
    c.name = name;
    c.rays = rays;
    return c;
}

// --lattice-sweep: uniform dense grids at 0.9 - 1.25x the default spacing, on the naive
// lattice (planes on the bounds) and on auto's (half a cell beyond them).
std::vector<Candidate> latticeSweep(const pb::scene::Bounds& bounds, float uniformSpacing,
                                    int rays) {
    std::vector<Candidate> sweep;
    for (int pad = 0; pad < 2; ++pad)
        for (float m : {0.9f, 0.95f, 1.0f, 1.05f, 1.1f, 1.15f, 1.2f, 1.25f}) {
            Candidate c = candidate(
                std::string(pad ? "pad " : "fit ") + std::to_string(m).substr(0, 4), rays);
            c.volumes.push_back(
                fitAutoVolume(bounds, m * uniformSpacing, 1 << 18,
                              pad ? AutoLattice::HalfCellMargin : AutoLattice::FitBounds)
                    .volume);
            sweep.push_back(c);
        }
    return sweep;
}

// The reference grid (half the default spacing), the uniform grids, and the adaptive
// placements within half of the uniform grid's memory, dense and sparse.
void placeCandidates(const pb::scene::Scene& s, const Options& o, Candidates& c) {
    const pb::scene::Bounds bounds = pb::raytrace::staticBakeBounds(s);
    const float uniformSpacing = defaultUniformSpacing(bounds);

    c.ref = candidate("reference", o.refRays);
    c.ref.volumes.push_back(fitAutoVolume(bounds, 0.5f * uniformSpacing, 1 << 18).volume);

    AutoPlacementRequest uniformReq;
    uniformReq.mode = AutoMode::Uniform;
    c.uniform = candidate("uniform", o.rays);
    AutoPlacementResult u = placeAutoVolumes(s, uniformReq);
    c.uniform.volumes = u.volumes;
    const double half = 0.5 * double(u.bytes);

    c.uniformHalf = candidate("uniform/2", o.rays);
    uniformReq.budgetBytes = half;
    c.uniformHalf.volumes = placeAutoVolumes(s, uniformReq).volumes;

    AutoPlacementRequest adaptiveReq;
    adaptiveReq.budgetBytes = half;
    adaptiveReq.adaptive.threads = o.threads;
    auto t0 = Clock::now();
    c.adaptiveDensePlacement = placeAutoVolumes(s, adaptiveReq);
    c.adaptiveDensePlaceSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    c.adaptiveDense = candidate("adaptive dense", o.rays);
    c.adaptiveDense.volumes = c.adaptiveDensePlacement.volumes;

    // The same two under the same budget, stored sparse (`--volumes auto`'s default).
    uniformReq.sparse = true;
    uniformReq.freeSpace = FreeSpace::Ranked;
    c.uniformHalfSparse = candidate("uniform/2 sparse", o.rays);
    c.uniformHalfSparse.sparse = true;
    c.uniformHalfSparse.budget = half;
    c.uniformHalfSparse.volumes = placeAutoVolumes(s, uniformReq).volumes;
    adaptiveReq.sparse = true;
    adaptiveReq.freeSpace = FreeSpace::Ranked;
    c.adaptive = candidate("adaptive", o.rays);
    c.adaptive.sparse = true;
    c.adaptive.budget = half;
    c.adaptivePlacement = placeAutoVolumes(s, adaptiveReq);
    c.adaptive.volumes = c.adaptivePlacement.volumes;
    // The same without the measured lattice search (LatticeShiftSearch.h): what it bought.
    adaptiveReq.latticeSearch = false;
    c.asPlaced = c.adaptive;
    c.asPlaced.name = "adaptive unshifted";
    c.asPlaced.volumes = placeAutoVolumes(s, adaptiveReq).volumes;

    if (o.latticeSweep) c.sweep = latticeSweep(bounds, uniformSpacing, o.rays);
}

// The truth at the surface points (the last bounce gathered at each point, the first from a
// 1-bounce bake of the reference grid) and at the mid-air points (issue 18: free-space points
// inside the reference grid's volume, not inside geometry (MidAirSamples.h), six normals each,
// against a sphere gather at the point).
Truth gatherTruth(const pb::scene::Scene& s, const pb::raytrace::RayScene& rays, const Candidate& ref,
                  const Options& o) {
    Truth t;
    const glm::vec3 refCell = ref.volumes[0].cellSize();
    const float minRefCell = std::min(refCell.x, std::min(refCell.y, refCell.z));
    t.tris = pb::raytrace::staticBakeTriangles(s);
    t.points = surfaceSamples(t.tris, rays, o.points, minRefCell);

    Candidate firstBounce = ref;
    firstBounce.bounces = 1;
    bakeCandidate(s, firstBounce, o.threads);
    t.firstBounceBakeSeconds = firstBounce.bakeSeconds;
    GatherSettings gs;
    gs.rays = o.gatherRays;
    gs.threads = o.threads;
    const std::vector<Scenario> scenarios = resolveScenarios({}, {}, s);
    auto t0 = Clock::now();
    const ProbeSampler firstBounceProbes(firstBounce.set, 0);
    t.surface = gatherIrradiance(rays, scenarios[0], s.lights, t.points, &firstBounceProbes, gs);
    t.gatherSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    t.midAir = midAirSamples(rays, ref.volumes, o.midAirPoints, minRefCell);
    t0 = Clock::now();
    t.midAirTruth = gatherIrradianceSphere(rays, scenarios[0], s.lights, t.midAir, kAxes,
                                           &firstBounceProbes, gs);
    t.midAirGatherSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return t;
}

// One candidate's row: memory, errors against the truth (and against the reference grid),
// the mid-air error and unlit lookups, the share of the surface on its probe planes.
nlohmann::json candidateRow(const Candidate& c, const Candidate& ref, const Truth& t) {
    MemoryReport m = memoryReport(c.set);
    const IrradianceErrors err = irradianceErrors(c.values, t.surface, ref.weights);
    const IrradianceErrors grid =
        &c == &ref ? IrradianceErrors{} : irradianceErrors(c.values, ref.values, ref.weights);
    // Every mid-air point counts: one a candidate leaves unlit (weight 0) is E = 0 there,
    // as the renderer's dynamic objects would see it (its ambient aside).
    const IrradianceErrors air = irradianceErrors(c.midAirValues, t.midAirTruth);
    std::size_t unlit = 0;
    for (float w : c.midAirWeights)
        unlit += w > 0.0f ? 0 : 1;
    glm::vec3 cell = c.volumes.back().cellSize();
    float onPlane = 0.0f;
    for (const ProbeVolume& v : c.volumes)
        onPlane = std::max(onPlane, surfaceOnProbePlanes(v, t.tris));
    return {{"placement", c.name},
            {"on_plane", onPlane},
            {"volumes", c.volumes.size()},
            {"probes", m.total.probes},
            {"stored_probes", m.total.storedProbes},
            {"mib", double(m.total.storedTotal()) / (1024.0 * 1024.0)},
            {"finest_spacing", std::max(cell.x, std::max(cell.y, cell.z))},
            {"far_probes", m.total.sparse.far},
            {"rays", c.rays},
            {"mean_relative_error", err.relative},
            {"nmae", err.nmae},
            {"grid_relative_error", grid.relative},
            {"mid_air_relative_error", air.relative},
            {"mid_air_unlit", unlit},
            {"points", err.points},
            {"bake_s", c.bakeSeconds}};
}

nlohmann::json runScene(const std::string& path, const Options& o) {
    pb::scene::Scene s = pb::scene::loadScene(path);
    Candidates c;
    placeCandidates(s, o, c);
    pb::raytrace::RayScene rays(s);
    const Truth t = gatherTruth(s, rays, c.ref, o);
    nlohmann::json rows = nlohmann::json::array();
    const std::vector<Candidate*> all = c.all();
    for (Candidate* candidate : all) {
        bakeCandidate(s, *candidate, o.threads);
        sampleAll(*candidate, t.points, t.midAir);
    }
    for (const Candidate* candidate : all)
        rows.push_back(candidateRow(*candidate, c.ref, t));
    const AutoPlacementResult& as = c.adaptivePlacement;
    return {{"scene", s.name},
            {"points_requested", o.points},
            {"points_on_surfaces", t.points.size()},
            {"adaptive_dense_place_s", c.adaptiveDensePlaceSeconds},
            {"gather_rays", o.gatherRays},
            {"gather_s", t.gatherSeconds},
            {"mid_air_points", t.midAir.size()},
            {"mid_air_gather_s", t.midAirGatherSeconds},
            {"reference_first_bounce_bake_s", t.firstBounceBakeSeconds},
            {"adaptive_dense_notes", c.adaptiveDensePlacement.notes},
            {"adaptive_notes", as.notes},
            {"adaptive_lattice_search",
             {{"shift_cells",
               {as.latticeShift.cells.x, as.latticeShift.cells.y, as.latticeShift.cells.z}},
              {"estimated_error_before", as.latticeShift.errorBefore},
              {"estimated_error_after", as.latticeShift.errorAfter},
              {"trials", as.latticeShift.trials},
              {"seconds", as.latticeSearchSeconds}}},
            {"rows", rows}};
}

// One scene's table (runScene's result).
void printTable(const nlohmann::json& r) {
    std::printf("\n%s: %zu surface points (adaptive dense placement %.2f s, truth gathered "
                "with %d rays in %.2f s)\n",
                r["scene"].get<std::string>().c_str(), r["points_on_surfaces"].get<std::size_t>(),
                r["adaptive_dense_place_s"].get<double>(), r["gather_rays"].get<int>(),
                r["gather_s"].get<double>());
    const auto& ls = r["adaptive_lattice_search"];
    std::printf("  adaptive lattice search: shift (%.1f, %.1f, %.1f) cells, estimated error %.4f "
                "-> %.4f, %d trial bakes in %.2f s\n",
                ls["shift_cells"][0].get<double>(), ls["shift_cells"][1].get<double>(),
                ls["shift_cells"][2].get<double>(), ls["estimated_error_before"].get<double>(),
                ls["estimated_error_after"].get<double>(), ls["trials"].get<int>(),
                ls["seconds"].get<double>());
    std::printf("  mid-air: %zu free-space points x 6 normals, sphere gather in %.2f s\n",
                r["mid_air_points"].get<std::size_t>(), r["mid_air_gather_s"].get<double>());
    std::printf("  %-18s %7s %8s %8s %9s %8s %8s %5s %9s %7s %9s %8s %8s %9s %6s\n", "placement",
                "volumes", "probes", "stored", "MiB", "finest", "far", "rays", "mean err", "nMAE",
                "grid err", "bake s", "on-plane", "air err", "unlit");
    for (const auto& row : r["rows"])
        std::printf("  %-18s %7zu %8zu %8zu %9.2f %8.3f %8zu %5d %9.4f %7.4f %9.4f %8.2f %8.4f "
                    "%9.4f %6zu\n",
                    row["placement"].get<std::string>().c_str(), row["volumes"].get<std::size_t>(),
                    row["probes"].get<std::size_t>(), row["stored_probes"].get<std::size_t>(),
                    row["mib"].get<double>(), row["finest_spacing"].get<double>(),
                    row["far_probes"].get<std::size_t>(), row["rays"].get<int>(),
                    row["mean_relative_error"].get<double>(), row["nmae"].get<double>(),
                    row["grid_relative_error"].get<double>(), row["bake_s"].get<double>(),
                    row["on_plane"].get<double>(), row["mid_air_relative_error"].get<double>(),
                    row["mid_air_unlit"].get<std::size_t>());
}

// The command line; exits with 2 on a bad one.
Options parseOptions(int argc, char** argv) {
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
            else if (a == "--gather-rays")
                o.gatherRays = std::stoi(next());
            else if (a == "--mid-air-points")
                o.midAirPoints = std::stoi(next());
            else if (a == "--threads")
                o.threads = std::stoi(next());
            else if (a == "--json")
                o.json = true;
            else if (a == "--lattice-sweep")
                o.latticeSweep = true;
            else if (a.rfind("--", 0) == 0)
                throw pb::Error(a + ": unknown option (--points N, "
                                    "--rays N, --ref-rays N, --gather-rays N, --mid-air-points N, "
                                    "--threads N, --json, --lattice-sweep)");
            else
                o.scenes.push_back(a);
        } catch (const std::logic_error&) {
            std::cerr << "bench_placement: " << a << ": expects an integer\n";
            std::exit(2);
        } catch (const pb::Error& e) {
            std::cerr << "bench_placement: " << e.what() << "\n";
            std::exit(2);
        }
    }
    if (o.scenes.empty()) o.scenes = pb::studies::sharedScenes();
    return o;
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
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
