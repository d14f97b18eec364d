#pragma once
// Rec. 709 luminance of linear RGB: the one number the bake weighs a colour by (emitter and
// lit-patch power for importance sampling, texel noise for the noise rounds, seed differences).
#include <glm/vec3.hpp>

namespace pb::probes {

inline float luminance(const glm::vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

} // namespace pb::probes
