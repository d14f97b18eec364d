#include "probes/bake/RayDirections.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace pb::probes {

float uniformFloat(std::uint64_t& state) {
    return float(splitmix64(state) >> 40) * (1.0f / 16777216.0f);
}

std::vector<glm::vec3> sphericalFibonacci(int n) {
    std::vector<glm::vec3> dirs(static_cast<size_t>(n > 0 ? n : 0));
    const double goldenFrac = (std::sqrt(5.0) - 1.0) * 0.5;
    for (int i = 0; i < n; ++i) {
        double z = 1.0 - (2.0 * i + 1.0) / n;
        double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        double f = double(i) * goldenFrac;
        double phi = 2.0 * M_PI * (f - std::floor(f));
        dirs[size_t(i)] = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    }
    return dirs;
}

glm::mat3 randomRotation(std::uint64_t& state) {
    float u1 = uniformFloat(state), u2 = uniformFloat(state), u3 = uniformFloat(state);
    const float twoPi = 6.28318530718f;
    float a = std::sqrt(1.0f - u1), b = std::sqrt(u1);
    glm::quat q(b * std::cos(twoPi * u3), a * std::sin(twoPi * u2), a * std::cos(twoPi * u2),
                b * std::sin(twoPi * u3));
    return glm::mat3_cast(glm::normalize(q));
}

std::uint64_t geometryStream(std::uint64_t seed) {
    std::uint64_t s = seed ^ 0x67656f6d65747279ull; // "geometry"
    return splitmix64(s);
}

std::uint64_t radianceStream(std::uint64_t seed, int scenario, int pass) {
    std::uint64_t s = seed ^ (std::uint64_t(std::uint32_t(scenario)) << 32) ^ std::uint32_t(pass);
    splitmix64(s);
    return splitmix64(s);
}

std::uint64_t roundStream(std::uint64_t seed, int scenario, int pass, int round) {
    std::uint64_t s = radianceStream(seed, scenario, pass) ^ (std::uint64_t(round) * 0x726f756e64ull);
    splitmix64(s);
    return splitmix64(s);
}

std::vector<glm::vec3> passDirections(int rays, std::uint64_t stream) {
    std::uint64_t state = stream;
    glm::mat3 rot = randomRotation(state);
    std::vector<glm::vec3> dirs = sphericalFibonacci(rays);
    for (glm::vec3& d : dirs)
        d = glm::normalize(rot * d);
    return dirs;
}

} // namespace pb::probes
