#pragma once
// The Adaptive Probe Volumes' L1 encoding (issue 19, item 2, optional; CPU emulation only):
// 16 B per probe in three 3D textures instead of L1's 3 x RGBA16F (24 B):
//   t0 RGBA16F: L0 red, green, blue and the red L1 x-ratio,
//   t1 RGBA8:   the green L1 ratios (the basis' y, z, x order) and the red L1 y-ratio,
//   t2 RGBA8:   the blue L1 ratios and the red L1 z-ratio,
// a ratio being c1 / (sqrt(3) c0) of the same colour mapped from [-1, 1] to [0, 1] (for a
// non-negative radiance |c1| <= sqrt(3) c0 in this basis, so it never clips). The hardware
// filters the stored texels; a lookup then decodes with the FILTERED L0: c1 = (2 t - 1)
// sqrt(3) L0. The extra error against the RGBA16F layout is the 8-bit rounding plus that
// filter-then-decode step (a ratio of blends is not a blend of ratios).
// Not wired to a switch or the GPU yet: ShSampleOptions::apv measures what it would cost
// (bench/results/2026-11-25-sh-technique-2.md).
#include <glm/glm.hpp>

namespace pb::probes {

struct ShApvTexels {
    glm::vec4 t0{0.0f}, t1{0.0f}, t2{0.0f};
};

// One probe's first 4 coefficients (radiance SH, RGB), as the three textures store them.
ShApvTexels encodeApv(const glm::vec3* coefficients);

// Blended texels (a trilinear sum of encodeApv's, weights summing to 1, or any premultiplied
// sum divided by its weight) -> the first 4 coefficients.
void decodeApv(const ShApvTexels& blended, glm::vec3* coefficients);

// Bytes per probe of the encoding's coefficient textures.
constexpr int kShApvBytesPerProbe = 8 + 4 + 4;

} // namespace pb::probes
