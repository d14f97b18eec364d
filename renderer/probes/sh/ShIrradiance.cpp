#include "probes/sh/ShIrradiance.h"

#include "core/ParallelFor.h"
#include "probes/ProbeSampler.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>

namespace pb::probes {

void shBasis(const glm::vec3& d, float out[kShL2Coefficients]) {
    // sqrt(1/4pi), sqrt(3/4pi), sqrt(15/4pi), sqrt(5/16pi), sqrt(15/16pi)
    out[0] = 0.282094792f;
    out[1] = 0.488602512f * d.y;
    out[2] = 0.488602512f * d.z;
    out[3] = 0.488602512f * d.x;
    out[4] = 1.092548431f * d.x * d.y;
    out[5] = 1.092548431f * d.y * d.z;
    out[6] = 0.315391565f * (3.0f * d.z * d.z - 1.0f);
    out[7] = 1.092548431f * d.x * d.z;
    out[8] = 0.546274215f * (d.x * d.x - d.y * d.y);
}

std::vector<glm::vec3> shProjectionDirections(int count) {
    // Spherical Fibonacci: equal-area latitude bands, golden-angle longitudes.
    std::vector<glm::vec3> dirs(static_cast<std::size_t>(count));
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = golden * i;
        dirs[size_t(i)] = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    }
    return dirs;
}

ShCoefficients projectRadiance(const std::vector<glm::vec3>& dirs,
                               const std::vector<glm::vec3>& radiance) {
    ShCoefficients c{};
    if (dirs.empty()) return c;
    const float w = 4.0f * 3.14159265f / float(dirs.size());
    float y[kShL2Coefficients];
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        shBasis(dirs[i], y);
        for (int k = 0; k < kShL2Coefficients; ++k)
            c[size_t(k)] += radiance[i] * (y[k] * w);
    }
    return c;
}

glm::vec3 shIrradiance(const glm::vec3* c, const glm::vec3& n, int count) {
    float y[kShL2Coefficients];
    shBasis(n, y);
    glm::vec3 e = c[0] * (kShBandA[0] * y[0]);
    for (int k = 1; k < 4 && k < count; ++k)
        e += c[k] * (kShBandA[1] * y[k]);
    for (int k = 4; k < count; ++k)
        e += c[k] * (kShBandA[2] * y[k]);
    return glm::max(e, glm::vec3(0.0f));
}

ShCoefficients projectIrradianceTile(const glm::ivec3& c, const ProbeTexture& irradiance) {
    static const std::vector<glm::vec3> dirs = shProjectionDirections(kShProjectionDirections);
    std::vector<glm::vec3> e(dirs.size());
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        const glm::vec2 t = tileCoord(c, dirs[i], kIrradianceInterior);
        float rgba[4];
        bilinearFetch(irradiance, t.x, t.y, c.y, rgba);
        e[i] = glm::vec3(rgba[0], rgba[1], rgba[2]);
    }
    // Irradiance SH, then band l divided by A_l: the radiance SH a lookup convolves back.
    ShCoefficients sh = projectRadiance(dirs, e);
    for (int k = 0; k < kShL2Coefficients; ++k)
        sh[size_t(k)] /= kShBandA[k == 0 ? 0 : k < 4 ? 1 : 2];
    return sh;
}

std::vector<glm::vec3> projectIrradianceTexture(const ProbeVolume& v,
                                                const std::vector<ProbeState>& states,
                                                const ProbeTexture& irradiance) {
    std::vector<glm::vec3> out(size_t(v.probeCount()) * kShL2Coefficients, glm::vec3(0.0f));
    for (int p = 0; p < v.probeCount(); ++p) {
        if (!ownsIrradiance(states[size_t(p)])) continue;
        const ShCoefficients sh = projectIrradianceTile(v.probeCoords(p), irradiance);
        std::copy(sh.begin(), sh.end(), out.begin() + std::ptrdiff_t(p) * kShL2Coefficients);
    }
    return out;
}

glm::vec3 toHalfPrecision(const glm::vec3& c) {
    constexpr float kMax = 65504.0f; // the largest half: beyond it a texel would be Inf
    const glm::vec3 clamped = glm::clamp(c, glm::vec3(-kMax), glm::vec3(kMax));
    return glm::vec3(glm::unpackHalf1x16(glm::packHalf1x16(clamped.x)),
                     glm::unpackHalf1x16(glm::packHalf1x16(clamped.y)),
                     glm::unpackHalf1x16(glm::packHalf1x16(clamped.z)));
}

std::vector<std::vector<std::vector<glm::vec3>>> projectSetToSh(const ProbeSet& set, int threads) {
    std::vector<std::vector<std::vector<glm::vec3>>> sh(set.irradiance.size());
    for (auto& s : sh)
        s.resize(set.volumes.size());
    const std::size_t volumes = set.volumes.size();
    parallelFor(set.irradiance.size() * volumes, threads, [&](std::size_t item, int) {
        const std::size_t s = item / volumes, v = item % volumes;
        sh[s][v] = projectIrradianceTexture(set.volumes[v], set.states[v], set.irradiance[s][v]);
        for (glm::vec3& c : sh[s][v])
            c = toHalfPrecision(c);
    });
    return sh;
}

} // namespace pb::probes
