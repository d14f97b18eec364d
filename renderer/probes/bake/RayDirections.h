#pragma once
// Probe ray directions: N spherical Fibonacci points, randomly rotated once per pass.
// One rotation per (seed, scenario, pass) is shared by every probe of that pass, so the
// cosine / cosine-power convolution weights are computed once per pass (ProbeConvolution.h).
// The RNG is splitmix64 (core/Hash.h) with explicit float conversion: the same seed gives the same
// directions on any machine and any thread count.
#include "core/Hash.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

// Uniform in [0, 1) from the top 24 bits.
float uniformFloat(std::uint64_t& state);

// Point i of n: z = 1 - (2i+1)/n, phi = 2*pi*frac(i * (sqrt(5)-1)/2), unit vectors.
std::vector<glm::vec3> sphericalFibonacci(int n);

// A uniformly distributed random rotation (Shoemake's unit quaternion from 3 uniforms).
glm::mat3 randomRotation(std::uint64_t& state);

// Streams of the bake: the geometry pass, and pass p of scenario s. The bake's geometry pass
// always uses kGeometrySeed (Baker.cpp says why); the radiance passes use the bake's seed.
constexpr std::uint64_t kGeometrySeed = 1;
std::uint64_t geometryStream(std::uint64_t seed);
std::uint64_t radianceStream(std::uint64_t seed, int scenario, int pass);
// Round r > 0 of a pass under a noise target (Baker.h): its own rotation and emitter samples.
std::uint64_t roundStream(std::uint64_t seed, int scenario, int pass, int round);

// The pass's directions: rotation(stream) applied to the Fibonacci set (volume-local).
std::vector<glm::vec3> passDirections(int rays, std::uint64_t stream);

} // namespace pb::probes
