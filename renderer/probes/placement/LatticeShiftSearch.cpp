#include "probes/placement/LatticeShiftSearch.h"

#include "core/ParallelFor.h"

#include <algorithm>

namespace pb::probes {

std::vector<ProbeVolume> shiftVolumes(const std::vector<ProbeVolume>& volumes,
                                      const glm::vec3& world) {
    std::vector<ProbeVolume> out = volumes;
    for (ProbeVolume& v : out)
        v.center += world;
    return out;
}

namespace {

// error() of every candidate, in the candidates' order, `concurrent` at a time.
std::vector<double> scoreAll(const std::vector<std::vector<ProbeVolume>>& candidates,
                             const PlacementScore& error, int concurrent) {
    std::vector<double> out(candidates.size());
    const int threads = std::max(1, std::min(concurrent, int(candidates.size())));
    parallelFor(candidates.size(), threads,
                [&](std::size_t i, int) { out[i] = error(candidates[i]); });
    return out;
}

} // namespace

LatticeShift searchLatticeShift(std::vector<ProbeVolume>& volumes, const glm::vec3& cell,
                                const PlacementScore& error, const PlacementFits& fits,
                                int concurrent) {
    LatticeShift out;
    glm::vec3 shift(0.0f); // in cells
    for (int axis = 0; axis < 3; ++axis) {
        // This axis's fitting trials (the unshifted placement first, on the first axis).
        std::vector<glm::vec3> trials;
        std::vector<std::vector<ProbeVolume>> candidates;
        if (axis == 0) candidates.push_back(volumes);
        for (float step : kLatticeShiftSteps) {
            glm::vec3 trial = shift;
            trial[axis] += step;
            std::vector<ProbeVolume> moved = shiftVolumes(volumes, trial * cell);
            if (!fits(moved)) continue;
            trials.push_back(trial);
            candidates.push_back(std::move(moved));
        }
        const std::vector<double> errors = scoreAll(candidates, error, concurrent);
        if (axis == 0) out.errorBefore = out.errorAfter = errors[0];
        const std::size_t first = axis == 0 ? 1 : 0;
        out.trials += int(trials.size());
        // In step order, the first of equal errors wins, as when scored one by one.
        glm::vec3 bestShift = shift;
        double bestError = out.errorAfter;
        for (std::size_t t = 0; t < trials.size(); ++t)
            if (errors[first + t] < bestError) {
                bestError = errors[first + t];
                bestShift = trials[t];
            }
        if (bestError < out.errorAfter * (1.0 - kLatticeShiftMargin)) {
            shift = bestShift;
            out.errorAfter = bestError;
        }
    }
    out.cells = shift;
    volumes = shiftVolumes(volumes, shift * cell);
    return out;
}

} // namespace pb::probes
