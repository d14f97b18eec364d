#include "probes/sh/ShApvEncoding.h"

#include "probes/sh/ShIrradiance.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {

namespace {
constexpr float kSqrt3 = 1.7320508f;

// c1 / (sqrt(3) c0) in [-1, 1] -> [0, 1]; 0.5 where c0 is not positive.
float ratio(float c1, float c0) {
    if (!(c0 > 0.0f)) return 0.5f;
    return std::clamp(c1 / (kSqrt3 * c0), -1.0f, 1.0f) * 0.5f + 0.5f;
}

float unorm8(float v) {
    return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}
} // namespace

ShApvTexels encodeApv(const glm::vec3* c) {
    // c[1..3]: the basis' (1,-1) ~ y, (1,0) ~ z, (1,1) ~ x.
    ShApvTexels t;
    const glm::vec3 l0 = toHalfPrecision(c[0]);
    const glm::vec3 rx = toHalfPrecision(glm::vec3(ratio(c[1].r, c[0].r), 0.0f, 0.0f));
    t.t0 = glm::vec4(l0, rx.x);
    t.t1 = glm::vec4(unorm8(ratio(c[1].g, c[0].g)), unorm8(ratio(c[2].g, c[0].g)),
                     unorm8(ratio(c[3].g, c[0].g)), unorm8(ratio(c[2].r, c[0].r)));
    t.t2 = glm::vec4(unorm8(ratio(c[1].b, c[0].b)), unorm8(ratio(c[2].b, c[0].b)),
                     unorm8(ratio(c[3].b, c[0].b)), unorm8(ratio(c[3].r, c[0].r)));
    return t;
}

void decodeApv(const ShApvTexels& b, glm::vec3* c) {
    const glm::vec3 l0(b.t0);
    auto l1 = [&](float t, float l0c) { return (2.0f * t - 1.0f) * kSqrt3 * l0c; };
    c[0] = l0;
    c[1] = glm::vec3(l1(b.t0.w, l0.r), l1(b.t1.x, l0.g), l1(b.t2.x, l0.b));
    c[2] = glm::vec3(l1(b.t1.w, l0.r), l1(b.t1.y, l0.g), l1(b.t2.y, l0.b));
    c[3] = glm::vec3(l1(b.t2.w, l0.r), l1(b.t1.z, l0.g), l1(b.t2.z, l0.b));
}

} // namespace pb::probes
