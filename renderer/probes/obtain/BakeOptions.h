#pragma once
// What every command that needs probes says about them: where they go (placement), how they
// are baked and stored. One struct, so `bake`, `bench`, `tune`, `respond` and the gate that are
// given the same options ask for the same probe file (ObtainProbes.h). The defaults are bake's.
#include "probes/ProbeSet.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/bake/Baker.h"
#include "probes/store/SparseStorage.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace pb::probes {

struct BakeOptions {
    // "auto" (adaptive, stored sparse unless `dense`), "auto-uniform" or a volumes TOML file.
    std::string volumes = "auto";
    float spacing = 0.0f;        // auto: the finest spacing; auto-uniform: the grid's; 0: default
    int autoLevels = 2, autoMaxChildren = 4;
    double budgetMib = 0.0;      // probe memory budget, one scenario resident; 0: none/default
    bool latticeSearch = true;   // auto: the measured lattice shift (LatticeShiftSearch.h)
    std::vector<std::string> scenarios; // names (day, night, a volumes file's); empty: day
    BakeSettings settings;       // rays, bounces, seed, format, noise target, samples, ...
    int threads = 0;             // 0: all cores; never changes the result
    bool sparse = false, dense = false; // storage overrides (both: an error, said by the caller)
    FreeSpace freeSpace = FreeSpace::Ranked; // stored sparse: what absent probes keep
};

// Sparse storage: `auto` stores sparse unless `dense`; auto-uniform and volumes files store
// dense unless `sparse`.
bool storesSparse(const BakeOptions& o);

// The automatic placement request of these options (its key decides the placement cache); the
// lattice search bakes its trials as the bake will be baked, under its first scenario.
AutoPlacementRequest autoPlacementRequest(const BakeOptions& o, const scene::Scene& s,
                                          AutoMode mode);

// Fills everything of `r` but the volumes: scenarios (with a volumes file's own), settings,
// storage. The free-space budget is the options' (the placement's own replaces it).
void setBakeSettings(const BakeOptions& o, const scene::Scene& s,
                     const std::vector<ScenarioSpec>& fileScenarios, BakeRequest& r);

// How many scenarios the request will hold, known without placing.
std::size_t scenarioCountBeforePlacement(const BakeOptions& o, const scene::Scene& s);

} // namespace pb::probes
