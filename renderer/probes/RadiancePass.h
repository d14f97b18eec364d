#pragma once
// One probe's irradiance in one bounce pass: trace the pass's rays, shade what they hit, and
// convolve (ProbeConvolution.h).
//
// Radiance arriving along a ray (Lambert, all surfaces diffuse):
//   miss                          -> sky radiance of the scenario
//   back face of single-sided     -> 0 (the inside of geometry; also what classification counts)
//   otherwise, at x with normal n facing the ray origin:
//       L = emissive + albedo / pi * (E_direct(x, n) + E_indirect(x, n))
// E_direct: DirectLight.h. E_indirect: the PREVIOUS pass's probes read with the CPU sampler
// at (x, n, view = -ray) without edge fade (0 in the first pass, or outside every volume).
// So pass b carries light that bounced up to b times before reaching the probe.
#include "probes/ProbeConvolution.h"
#include "probes/ProbeSampler.h"
#include "probes/RayScene.h"
#include "probes/Scenario.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

struct RadianceScratch {
    std::vector<float> r, g, b;
};

struct RayCounters {
    std::uint64_t primary = 0, shadow = 0;
};

// outRgb: the 6x6 interior, RGB per texel, row-major.
void bakeProbeRadiance(const RayScene& rs, const Scenario& sc,
                       const std::vector<scene::Light>& lights, const glm::mat3& volumeRotation,
                       const glm::vec3& probeWorld, const std::vector<glm::vec3>& localDirs,
                       const ProbeConvolution& conv, const ProbeSampler* previous,
                       RadianceScratch& scratch, float* outRgb, RayCounters& counters);

} // namespace pb::probes
