#pragma once
// Spherical-harmonic irradiance probes, the second GI technique (gi.technique=sh_l1|sh_l2):
// per probe 9 real SH coefficients x RGB of RADIANCE (L2; L1 is the first 4), in the volume's
// local frame. A lookup convolves them with the clamped-cosine lobe (Ramamoorthi & Hanrahan
// 2001: A0 = pi, A1 = 2pi/3, A2 = pi/4) to get irradiance.
//
// Where the coefficients come from: every radiance pass of the bake projects each probe's own
// samples (summed over the passes, as the octahedral tiles are) (RadianceSlab::projectSh: 4 pi / N sum L(w) Y(w) over its rays, plus its emitter and
// lit-surface samples' shares; noise rounds averaged as the texels are), the same samples its
// octahedral irradiance tile convolves, so the SH probes sit on exactly DDGI's bake. Only a
// nested child's blended ring probes (NestingBlend.h) take the map projection below
// (projectIrradianceTile: the final tile at kShProjectionDirections spherical Fibonacci
// directions, band l divided by A_l; by Funk-Hecke the radiance band-limited to L2, up to the
// map's filtering), since their blend happens on the map. Measured against that projection for
// every probe: bench/results/2026-11-25-sh-technique-2.md.
#include "probes/ProbeLayout.h"
#include "probes/ProbeSet.h"

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

constexpr int kShL1Coefficients = 4;
constexpr int kShL2Coefficients = 9;
constexpr int kShProjectionDirections = 1024;

// GPU bytes per probe of the SH textures (renderer/passes/GpuShTextures.h): L1 3 x RGBA16F,
// L2 7 x RGBA16F (the 5 quadratic coefficients x RGB in 4 texels), + 1 R8 validity each.
constexpr std::size_t shGpuBytesPerProbe(int coefficients) {
    return coefficients == kShL1Coefficients   ? 3 * 8 + 1
           : coefficients == kShL2Coefficients ? 7 * 8 + 1
                                               : 0;
}

// The cosine-lobe convolution per band (l = 0, 1, 2).
inline constexpr float kShBandA[3] = {3.14159265f, 2.09439510f, 0.78539816f};

using ShCoefficients = std::array<glm::vec3, kShL2Coefficients>;

// Whether the SH technique counts a probe as valid: valid for DDGI and its lattice point (where
// the SH lookup places it) outside geometry.
inline bool shProbeValid(const ProbeState& s) {
    return s.valid && !s.insideAtLattice;
}

// Real SH basis, order (l,m): (0,0) (1,-1) (1,0) (1,1) (2,-2) (2,-1) (2,0) (2,1) (2,2);
// `d` unit.
void shBasis(const glm::vec3& d, float out[kShL2Coefficients]);

// `count` spherical Fibonacci directions (unit, deterministic): the projection's quadrature.
std::vector<glm::vec3> shProjectionDirections(int count);

// Radiance samples (one per direction, directions uniform over the sphere) -> radiance SH,
// each sample weighted 4 pi / count.
ShCoefficients projectRadiance(const std::vector<glm::vec3>& dirs,
                               const std::vector<glm::vec3>& radiance);

// Irradiance at unit normal `n` (local frame) from radiance SH, with the first
// `coefficients` (4: L1, 9: L2) terms, clamped at 0 (a truncated series can ring negative).
glm::vec3 shIrradiance(const glm::vec3* coefficients, const glm::vec3& n, int count);

// One probe's irradiance tile (grid coords `c`) projected as below: radiance SH, band l
// divided by A_l.
ShCoefficients projectIrradianceTile(const glm::ivec3& c, const ProbeTexture& irradiance);

// The map projection of one volume's irradiance texture (RGBA, float, borders filled):
// probeCount() x 9 coefficients, probe-major. Probes that are not stored get zeros.
std::vector<glm::vec3> projectIrradianceTexture(const ProbeVolume& v,
                                                const std::vector<ProbeState>& states,
                                                const ProbeTexture& irradiance);

// `c` rounded to half floats (clamped to +-65504): the SH textures are RGBA16F, and rounding
// in the bake makes the CPU sampler and the GPU see the same coefficients.
glm::vec3 toHalfPrecision(const glm::vec3& c);

// Every scenario and volume of `set` ([scenario][volume]) by the map projection of its
// (unquantised) irradiance, rounded by toHalfPrecision: SH for sets built without a bake
// (tests) and the comparison the bake's ray projection was chosen by.
std::vector<std::vector<std::vector<glm::vec3>>> projectSetToSh(const ProbeSet& set, int threads);

} // namespace pb::probes
