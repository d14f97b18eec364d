#pragma once
// How far probe irradiance at surface points is from the truth there (bench_placement, the
// placement's lattice search). Over the points with covered[i] > 0.99 (all when `covered` is
// empty):
//   relative = mean_i sum_rgb |E_i - T_i| / max(sum_rgb T_i, 10% of the mean of sum_rgb T)
//              (the floor keeps a light leak onto a nearly black point from dominating)
//   nmae     = mean_i sum_rgb |E_i - T_i| / mean_i sum_rgb T_i
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

struct IrradianceErrors {
    double relative = 0.0, nmae = 0.0; // NaN when no point counts
    std::size_t points = 0;
};

IrradianceErrors irradianceErrors(const std::vector<glm::vec3>& values,
                                  const std::vector<glm::vec3>& truth,
                                  const std::vector<float>& covered = {});

} // namespace pb::probes
