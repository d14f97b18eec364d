#include "scene/SkyVisibility.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pb::scene {

namespace {

// A fixed-seed 64-bit LCG (Knuth's MMIX constants): floats from the top 24 bits, exact on
// every CPU.
struct Lcg {
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    float next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return float(state >> 40) * (1.0f / 16777216.0f);
    }
};

// A cosine-weighted direction about unit `n`: a uniform point of the unit disk (by rejection)
// lifted onto the hemisphere (Malley's method); sqrt is exactly rounded everywhere, unlike
// sin and cos.
glm::vec3 cosineDirection(const glm::vec3& n, Lcg& rng) {
    float x, y;
    do {
        x = 2.0f * rng.next() - 1.0f;
        y = 2.0f * rng.next() - 1.0f;
    } while (x * x + y * y > 1.0f);
    const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
    // An orthonormal basis around n (Duff et al. 2017).
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::vec3 bt(b, sign + n.y * n.y * a, -n.y);
    return glm::normalize(t * x + bt * y + n * z);
}

} // namespace

float meanSkyVisibility(const RayGrid& grid, int samples) {
    if (grid.empty() || samples <= 0) return 0.0f;
    Bounds bounds = grid.bounds();
    // A flat scene (a floor alone) gets a little height on its flat axes, or every eye would
    // lie in its plane and see nothing.
    const float diagonal = glm::length(bounds.size());
    for (int a = 0; a < 3; ++a) {
        const float grow = std::max(0.0f, 0.01f * diagonal - (bounds.max[a] - bounds.min[a]));
        bounds.min[a] -= 0.5f * grow;
        bounds.max[a] += 0.5f * grow;
    }
    const glm::vec3 size = bounds.size();
    const float lift = 1e-4f * diagonal; // off the surface, past RayGrid's own minimum distance
    Lcg rng;
    int open = 0, seen = 0;
    for (int s = 0; s < samples * 8 && seen < samples; ++s) {
        const glm::vec3 eye = bounds.min + size * glm::vec3(rng.next(), rng.next(), rng.next());
        glm::vec3 d;
        float len2;
        do {
            d = glm::vec3(rng.next(), rng.next(), rng.next()) * 2.0f - 1.0f;
            len2 = glm::dot(d, d);
        } while (len2 > 1.0f || len2 < 1e-6f);
        d /= std::sqrt(len2);
        const RayHit hit = grid.cast(eye, d, 2.0f * diagonal);
        if (!std::isfinite(hit.distance) || hit.backFacing) continue;
        ++seen;
        const glm::vec3 p = eye + d * hit.distance;
        const glm::vec3 r = cosineDirection(hit.normal, rng);
        if (!std::isfinite(grid.cast(p + hit.normal * lift, r, 2.0f * diagonal).distance)) ++open;
    }
    // Nothing seen from inside the bounds (every surface faces away from them): nothing
    // encloses anything, the sky is open.
    return seen > 0 ? float(open) / float(seen) : 1.0f;
}

float meanSkyVisibility(const Scene& scene, int samples) {
    const RayGrid grid(scene);
    return meanSkyVisibility(grid, samples);
}

} // namespace pb::scene
