#pragma once
// An estimate of the irradiance error a probe placement will show, cheap enough to compare a
// handful of candidate lattices while `--volumes auto` places its volumes.
//
// Why measure rather than score geometry: with probes a cell or two apart, the error at a
// point is dominated by light leaking through thin or double-sided surfaces, and whether a
// lattice leaks depends on where its probes fall relative to every wall, floor and roof at
// once. Shifting the same lattice by a fraction of a cell changes bench_placement's error on
// Sponza by +-10% while geometric scores (surface on probe planes, LatticeAlignment.h) do not
// predict which shift wins. So: bake the candidate cheaply and look.
//
// The truth is gathered at `points` surface samples (SurfaceSamples.h) with `gatherRays` rays
// (SurfaceGather.h): the last bounce exact, the earlier ones (bounces > 1) read at the hits
// from a finer grid baked once (one volume over the static bounds at `truthSpacing`,
// `probeRays` rays, stored sparse: the gather's hits lie on surfaces, whose cells keep all
// their corner probes, so the probes in open air need no rays; on the five shared scenes,
// rooms and the courtyard the searches chose the same shifts with it, to the same
// estimates). Each candidate is baked as the real bake will be (`bounces`) with `probeRays`
// rays, sampled at the same points, and scored with irradianceErrors().relative
// (IrradianceError.h). The bounce count matters: with one bounce the dark regions that only
// the second bounce lights dominate the error, and the ranking of shifts changed on the
// space-ship hallway. Built once per scene and scenario; deterministic for any thread count.
#include "probes/ProbeVolume.h"
#include "raytrace/RayScene.h"
#include "probes/Scenario.h"
#include "probes/bake/SurfaceGather.h"
#include "raytrace/StaticTriangles.h"
#include "scene/Scene.h"

#include <vector>

namespace pb::probes {

struct PlacementErrorSettings {
    int points = 8000;
    int gatherRays = 64;
    int probeRays = 32;
    int bounces = 2; // the bake's
    // Of the surface samples. Not bench_placement's seed: the benchmark must score the
    // placement on points the search never saw.
    std::uint64_t seed = 0x51A7CE5Du;
    int threads = 0;
};

class PlacementErrorEstimate {
public:
    // rays: the scene's BVH (the placement's own; every trial bake traces it too, so it must
    // outlive the estimate). sealedBelow: surface samples whose hemisphere is closed within
    // this distance are skipped (SurfaceSamples.h). truthSpacing: the grid spacing of the
    // truth's earlier bounces. Throws pb::Error for a scene without static surface.
    PlacementErrorEstimate(const scene::Scene& scene, const raytrace::RayScene& rays,
                           const Scenario& scenario, float sealedBelow, float truthSpacing,
                           const PlacementErrorSettings& settings = {});
    // The candidate's mean relative error (sparse: stored as `bake --sparse` stores it).
    // `threads` (0: all cores) never changes the result; < 0: the settings' count. Safe to
    // call from several threads at once (the lattice search scores an axis's shifts so).
    // `kept`: sparseKeptProbes of each volume when the caller has them (BakeRequest::keptProbes).
    double relativeError(const std::vector<ProbeVolume>& volumes, bool sparse,
                         int threads = -1,
                         const std::vector<std::vector<std::uint8_t>>* kept = nullptr) const;
    std::size_t pointCount() const { return points_.size(); }

private:
    const scene::Scene& scene_;
    const raytrace::RayScene& rays_; // one BVH for every trial bake
    Scenario scenario_;
    PlacementErrorSettings settings_;
    std::vector<raytrace::WorldTriangle> triangles_; // the scene's, for every trial's sparse mask
    std::vector<GatherPoint> points_;
    std::vector<glm::vec3> truth_;
};

} // namespace pb::probes
