#pragma once
// The studies' one bake: a scene and the few options the studies vary -> baked probes. Every
// study bakes through this instead of filling a BakeRequest by hand, so a study states only what
// it changes from `bake`'s defaults (renderer/probes/bake/Baker.h has the rest).
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace pb::studies {

struct BakeOptions {
    std::vector<probes::ProbeVolume> volumes;
    // Scenario names (probes/Scenario.h resolveScenarios); empty: "day", as `bake` does.
    std::vector<std::string> scenarios;
    int rays = probes::BakeSettings{}.raysPerProbe;
    int bounces = probes::BakeSettings{}.bounces;
    // The converged bake's noise target (BakeSettings::noiseTarget); 0: one round of rays.
    float noiseTarget = probes::BakeSettings{}.noiseTarget;
    bool sparse = false;
    // With `sparse`: what the probes left out keep, and the budget the Ranked tiles fill
    // (BakeRequest::freeSpace, freeSpaceBudgetBytes).
    probes::FreeSpace freeSpace = probes::FreeSpace::StandIns;
    double freeSpaceBudgetBytes = 0.0;
    int threads = 0; // 0: all cores (never changes the result)
};

// Bakes `scene` with `options`, the rest of the bake's settings at their defaults.
probes::ProbeSet bake(const scene::Scene& scene, const BakeOptions& options);

} // namespace pb::studies
