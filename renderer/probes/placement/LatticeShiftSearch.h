#pragma once
// Where `--volumes auto` lets its lattice sit: the placement shifted as a whole by a fraction
// of its finest cell, chosen by measured error (PlacementError.h) rather than by a geometric
// score.
//
// Coordinate descent, one sweep: along world x, then y, then z, coarse to fine. First the
// shifts kLatticeCoarseSteps (fractions of the finest cell, added to the shift found so far),
// then those of kLatticeFineSteps a tenth of a cell either side of the best of them, and of the
// current shift too unless that best clears the margin; keep the one with the lowest estimated
// error when it beats the current one by more than kLatticeShiftMargin (relative), and only
// shifts whose placement still `fits` (a sparse placement stores a different number of probes
// once shifted). 3 * (4 + 3) trial bakes at most, on the same grid of tenths of a cell as trying
// all eight steps (3 * 8 bakes, until 2026-12-04), and 15 - 18 on the shared scenes: where the
// error falls towards its best step the coarse stage lands next to it and the fine stage finds
// it; a minimum that the coarse steps miss entirely is not found.
// A stage's trials do not depend on each other, so they may be scored side by side
// (`cores`); the choice is made afterwards in step order (coarse, then fine), so it is the
// same for any concurrency.
//
// Why it is safe to shift: auto's outer volume reaches half of its own cell beyond the scene
// bounds (AutoLattice::HalfCellMargin), and no shift reaches half of the finest cell, so the
// bounds stay covered; the volumes move together, so the nesting stays as placed.
#include "probes/ProbeVolume.h"

#include <array>
#include <functional>
#include <vector>

namespace pb::probes {

constexpr std::array<float, 4> kLatticeCoarseSteps{-0.4f, -0.2f, 0.2f, 0.4f};
constexpr std::array<float, 4> kLatticeFineSteps{-0.3f, -0.1f, 0.1f, 0.3f};
// Trial bakes per axis at most: the coarse steps and three fine ones (next to the best coarse
// step and to the current shift).
constexpr int kLatticeTrialsPerAxis = int(kLatticeCoarseSteps.size()) + 3;
// How much lower a shift's estimated error must be to be kept: above the estimate's noise (the
// hallway once preferred a shift by 1.3% that the benchmark scores 10% worse). 5% left out the
// garden's x -0.4 (-3.0%) and z +0.1 (-4.0%), which the placement benchmark scores 5.5% better;
// at 2% only the garden's and the apartment's placements change, both for the better
// (studies/results/2026-11-29-lattice-search-margin.md).
constexpr double kLatticeShiftMargin = 0.02;

struct LatticeShift {
    glm::vec3 cells{0.0f};                      // the shift kept, in finest cells per world axis
    double errorBefore = 0.0, errorAfter = 0.0; // estimated relative errors (PlacementError.h)
    int trials = 0;                             // trial bakes (not counting the unshifted one)
};

// The volumes shifted by `world` (every volume's centre).
std::vector<ProbeVolume> shiftVolumes(const std::vector<ProbeVolume>& volumes,
                                      const glm::vec3& world);

// The estimated error of a placement, computed on `threads` threads (the result must not depend
// on them: a bake's bytes do not).
using PlacementScore = std::function<double(const std::vector<ProbeVolume>&, int threads)>;
using PlacementFits = std::function<bool(const std::vector<ProbeVolume>&)>;

// Searches the shift of `volumes` (finest cell `cell`, world units per axis) and applies the
// one kept to `volumes`. `error`: the estimated error of a placement
// (PlacementErrorEstimate::relativeError); `fits`: whether it is still within the budget,
// always called on the calling thread. `cores` > 1: a stage's trials run side by side, one
// per core with one thread each (the unshifted estimate beside the first axis's trials), and
// the last trials of a stage, fewer than the cores, share all of them: a lone trial keeps 2
// cores about 70% busy, an idle core nothing. `error` must then be safe to call from several
// threads.
LatticeShift searchLatticeShift(std::vector<ProbeVolume>& volumes, const glm::vec3& cell,
                                const PlacementScore& error, const PlacementFits& fits,
                                int cores = 1);

} // namespace pb::probes
