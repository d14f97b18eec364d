#include "truth/GBufferAlbedo.h"

#include <algorithm>
#include <cmath>

namespace pb::truth {

float throughSrgb8(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    const float stored = std::floor(encoded * 255.0f + 0.5f) / 255.0f;
    return stored <= 0.04045f ? stored / 12.92f : std::pow((stored + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 asGBufferStoresAlbedo(const glm::vec3& albedo) {
    return {throughSrgb8(albedo.x), throughSrgb8(albedo.y), throughSrgb8(albedo.z)};
}

} // namespace pb::truth
