#pragma once
// How much a bake depends on its random seed: two probe sets of one scene, baked alike but for
// the seed, looked up (CPU sampler, first scenario, surface normal as the view) at the same
// random surface points (SurfaceSamples.h). Per point the relative difference of the
// irradiance's luminance |Y1 - Y2| / ((Y1 + Y2) / 2), over the points that both sets light.
// Seed noise is what the converged bake (BakeSettings::noiseTarget, emitter sampling) removes;
// bench_bake_noise prints it and a test holds the built-in Cornell box to <= 3%.
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <cstddef>

namespace pb::studies {

struct SeedDifference {
    std::size_t points = 0; // compared (lit by both)
    double mean = 0.0, median = 0.0, p90 = 0.0;
    // The same split by brightness: the dimmest quarter of the points (light that arrives
    // after bounces, through doors) against the rest.
    double dimQuarterBelow = 0.0; // the irradiance luminance splitting them
    double dimMean = 0.0, brightMean = 0.0;
};

// region (optional): only the points inside it count (one room of a scene, say).
SeedDifference seedDifference(const scene::Scene& scene, const probes::ProbeSet& a,
                              const probes::ProbeSet& b, int points,
                              const scene::Bounds* region = nullptr);

} // namespace pb::studies
