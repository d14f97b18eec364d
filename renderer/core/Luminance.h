#pragma once
// Rec. 709 (sRGB primaries) relative luminance of a linear RGB colour, in float:
//     Y = 0.2126 R + 0.7152 G + 0.0722 B, summed in that order.
// The one number a colour is weighed by across the project (the bake's light tables and noise
// rounds, the path tracer's light choice, the default view's light test, the benchmarks' error
// figures). The exact float expression matters: the bake's bytes depend on it.
// Kept apart: metrics/ColourSpaces.cpp (FLIP's more precise matrix) and the sums in double of
// frame/GiCoverageView.cpp and probes/sh/WallLeak.cpp.
#include <glm/vec3.hpp>

namespace pb {

inline float luminance(const glm::vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

// The same of three consecutive floats R, G, B (a texel, a pixel, a ray's radiance).
inline float luminance(const float* rgb) {
    return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

} // namespace pb
