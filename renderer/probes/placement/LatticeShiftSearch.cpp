#include "probes/placement/LatticeShiftSearch.h"

#include "core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {

std::vector<ProbeVolume> shiftVolumes(const std::vector<ProbeVolume>& volumes,
                                      const glm::vec3& world) {
    std::vector<ProbeVolume> out = volumes;
    for (ProbeVolume& v : out)
        v.center += world;
    return out;
}

namespace {

// error() of every candidate, in the candidates' order, on `cores` cores: whole rounds of one
// trial per core first, then the rest side by side with the cores shared among them.
std::vector<double> scoreAll(const std::vector<std::vector<ProbeVolume>>& candidates,
                             const PlacementScore& error, int cores) {
    std::vector<double> out(candidates.size());
    const std::size_t n = candidates.size(), per = std::size_t(std::max(1, cores));
    for (std::size_t done = 0; done < n;) {
        const std::size_t left = n - done, batch = left >= per ? left / per * per : left;
        const int workers = int(std::min(batch, per));
        const int each = std::max(1, cores / workers);
        parallelFor(batch, workers,
                    [&](std::size_t i, int) { out[done + i] = error(candidates[done + i], each); });
        done += batch;
    }
    return out;
}

} // namespace

LatticeShift searchLatticeShift(std::vector<ProbeVolume>& volumes, const glm::vec3& cell,
                                const PlacementScore& error, const PlacementFits& fits, int cores) {
    LatticeShift out;
    glm::vec3 shift(0.0f); // in cells
    for (int axis = 0; axis < 3; ++axis) {
        // The axis's best so far, against which each stage's trials compete (in step order, the
        // first of equal errors wins, as when scored one by one); on the first axis the
        // unshifted placement, scored beside the coarse trials.
        glm::vec3 bestShift = shift;
        double bestError = out.errorAfter;
        auto bestClearsMargin = [&] {
            return bestError < out.errorAfter * (1.0 - kLatticeShiftMargin);
        };
        // Scores this axis's fitting trials at `steps` (cells added to the current shift).
        auto stage = [&](const std::vector<float>& steps, bool withUnshifted) {
            std::vector<glm::vec3> trials;
            std::vector<std::vector<ProbeVolume>> candidates;
            if (withUnshifted) candidates.push_back(volumes);
            for (float step : steps) {
                glm::vec3 trial = shift;
                trial[axis] += step;
                std::vector<ProbeVolume> moved = shiftVolumes(volumes, trial * cell);
                if (!fits(moved)) continue;
                trials.push_back(trial);
                candidates.push_back(std::move(moved));
            }
            const std::vector<double> errors = scoreAll(candidates, error, cores);
            const std::size_t first = withUnshifted ? 1 : 0;
            if (withUnshifted) bestError = out.errorBefore = out.errorAfter = errors[0];
            out.trials += int(trials.size());
            for (std::size_t t = 0; t < trials.size(); ++t)
                if (errors[first + t] < bestError) {
                    bestError = errors[first + t];
                    bestShift = trials[t];
                }
        };
        stage({kLatticeCoarseSteps.begin(), kLatticeCoarseSteps.end()}, axis == 0);
        // The fine steps a tenth of a cell either side of the best coarse step, and of the
        // current shift too unless that step clears the margin: a gain under the margin may be
        // the estimate's noise, and the current shift's neighbours may hold the real minimum.
        std::vector<float> centres{bestShift[axis] - shift[axis]};
        if (!bestClearsMargin()) centres.push_back(0.0f);
        std::vector<float> fine;
        for (float step : kLatticeFineSteps)
            for (float centre : centres)
                if (std::abs(std::abs(step - centre) - 0.1f) < 0.05f) {
                    fine.push_back(step);
                    break;
                }
        stage(fine, false);
        if (bestClearsMargin()) {
            shift = bestShift;
            out.errorAfter = bestError;
        }
    }
    out.cells = shift;
    volumes = shiftVolumes(volumes, shift * cell);
    return out;
}

} // namespace pb::probes
