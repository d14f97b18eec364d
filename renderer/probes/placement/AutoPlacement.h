#pragma once
// `bake --volumes auto | auto-uniform`: automatic probe volumes for a scene, within a probe
// count cap and an optional memory budget.
//
//   adaptive (`auto`, the default): an outer volume over the static bounds plus nested child
//       volumes near surfaces (AdaptivePlacement.h). `spacing` is the FINEST spacing (the
//       deepest child tier); the outer volume uses spacing * 2^levels. Default: the
//       placement gets the memory of the default uniform grid (about 4096 probes) as its
//       budget, starting from half the default uniform spacing near surfaces.
//   uniform (`auto-uniform`): one volume fitted to the static bounds (AutoVolume.h), the
//       behaviour `auto` had before adaptive placement; the comparison baseline.
//
// Budget: when the placement needs more than `budgetBytes` (probe memory in `format`, one
// scenario resident, as `probebench memory` counts it) or more than `maxProbes` probes in all,
// the spacing grows until it fits (a few placements: growth, then bisection to use as much of
// the budget as possible) and `notes` says so. A budget that not even a 2x2x2 volume fits is
// an error.
#include "probes/placement/AdaptivePlacement.h"
#include "probes/placement/AutoVolume.h"
#include "probes/placement/LatticeShiftSearch.h"
#include "probes/Scenario.h"
#include "probes/StorageFormat.h"
#include "probes/store/SparseStorage.h"
#include "scene/Scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pb::probes {

enum class AutoMode { Adaptive, Uniform };

struct AutoPlacementRequest {
    AutoMode mode = AutoMode::Adaptive;
    AdaptiveOptions
        adaptive; // adaptive.spacing <= 0: default; uniform mode uses it as the grid spacing
    double budgetBytes = 0.0; // <= 0: no budget
    StorageFormat format = StorageFormat::Rgba16f;
    long long maxProbes = kAutoMaxProbes;
    // The bake stores sparse (`bake --sparse`, SparseStorage.h): the budget counts only the
    // probes at surface cells (+ the indirection), so a finer spacing fits the same memory.
    bool sparse = false;
    // With `sparse`: what the probes it leaves out keep (SparseStorage.h FreeSpace).
    // Irradiance: every one keeps its irradiance tile, which the budget then counts. Ranked
    // (what `bake` asks for): the bake's tiles fill what the placement leaves of the budget
    // (FreeSpaceTiles.h); when the adaptive placement that fills the budget leaves them less
    // than kFreeSpaceTileShare of it, it is made again into the rest, if that costs at most
    // 5% of its finest spacing (a placement the budget sets, not one at a given spacing;
    // auto-uniform, the comparison baseline, is never placed again).
    FreeSpace freeSpace = FreeSpace::StandIns;
    // `auto` under a budget (the default one included) ends with a measured search of where
    // its lattice sits (LatticeShiftSearch.h): up to 25 one-bounce trial bakes of the chosen
    // placement. false: keep the lattice as placed (`bake --no-lattice-search`).
    bool latticeSearch = true;
    // The light the search measures under: the bake's first scenario. Unset: the scene's own
    // sun and sky.
    std::optional<Scenario> lighting;
    int bounces = 2; // the bake's, which the search's trial bakes repeat
    // Told of each step, so a long placement is not silent (`bake` prints it): stage
    // "placement" with `done` = placements tried so far (total 0: not known ahead), or
    // "lattice search" with `done` of at most `total` error estimates (the unshifted one + the
    // trial bakes). Never changes the result.
    std::function<void(const std::string& stage, int done, int total)> progress;
};

struct AutoPlacementResult {
    std::vector<ProbeVolume> volumes;
    float spacing = 0.0f;       // the finest spacing used (uniform: the grid spacing)
    int levels = 0;             // adaptive tiers placed below the outer volume (0: one volume)
    float onProbePlanes = 0.0f; // surface share on probe planes (LatticeAlignment.h), adaptive
    std::size_t bytes = 0;      // stored probe memory in the request's format (sparse: as stored)
    long long probes = 0;
    int placements = 0;           // how many placements the budget loop tried
    double budgetBytes = 0.0;     // the budget applied (0: none), free-space tiles included
    bool defaultBudget = false;   // adaptive, no spacing or budget given: the default uniform
                                  // grid's memory (coarsening to it is not reported in notes)
    AdaptiveStats stats;          // adaptive only: of the placement returned
    bool latticeSearched = false; // the lattice search ran; latticeShift is its result
    LatticeShift latticeShift;
    double latticeSearchSeconds = 0.0;
    std::vector<std::string> notes; // e.g. the spacing grew to fit the budget
};

// "auto" -> Adaptive, "auto-uniform" -> Uniform; false for anything else (a file name).
bool parseAutoMode(const std::string& text, AutoMode& mode);
const char* autoModeName(AutoMode mode);

// Throws pb::Error (one line naming the option) for an empty scene, bad options or a budget
// too small for any placement.
AutoPlacementResult placeAutoVolumes(const scene::Scene& scene,
                                     const AutoPlacementRequest& request);

// The default uniform spacing (about kAutoTargetProbes probes over the grown bounds).
float defaultUniformSpacing(const scene::Bounds& staticBounds);

} // namespace pb::probes
