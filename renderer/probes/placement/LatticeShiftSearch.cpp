#include "probes/placement/LatticeShiftSearch.h"

namespace pb::probes {

std::vector<ProbeVolume> shiftVolumes(const std::vector<ProbeVolume>& volumes,
                                      const glm::vec3& world) {
    std::vector<ProbeVolume> out = volumes;
    for (ProbeVolume& v : out)
        v.center += world;
    return out;
}

LatticeShift searchLatticeShift(std::vector<ProbeVolume>& volumes, const glm::vec3& cell,
                                const PlacementScore& error, const PlacementFits& fits) {
    LatticeShift out;
    out.errorBefore = out.errorAfter = error(volumes);
    glm::vec3 shift(0.0f); // in cells
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 bestShift = shift;
        double bestError = out.errorAfter;
        for (float step : kLatticeShiftSteps) {
            glm::vec3 trial = shift;
            trial[axis] += step;
            const std::vector<ProbeVolume> moved = shiftVolumes(volumes, trial * cell);
            if (!fits(moved)) continue;
            ++out.trials;
            const double e = error(moved);
            if (e < bestError) {
                bestError = e;
                bestShift = trial;
            }
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
