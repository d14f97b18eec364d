#pragma once
// The irradiance a Lambertian surface received, from a read-back frame: E = pi * L / albedo,
// with the GBuffer's sRGB8 albedo decoded as the lighting decodes it (albedo floored at 1e-3 so
// black texels stay finite). Shared by the dynamic-object tests.
#include "image/Image.h"
#include "metrics/ColourSpaces.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace pb::test {

inline glm::vec3 lambertIrradiance(const image::ImageF& radiance, const image::Image8& albedo,
                                   int x, int y) {
    glm::vec3 e;
    for (int c = 0; c < 3; ++c)
        e[c] = float(M_PI * radiance.at(x, y, c) /
                     std::max(metrics::colour::srgbToLinear(albedo.at(x, y, c) / 255.0), 1e-3));
    return e;
}

} // namespace pb::test
