#include "truth/GBufferAlbedo.h"

#include "truth/Srgb.h"

#include <cmath>

namespace pb::truth {

float throughSrgb8(float linear) {
    return srgb8ToLinear(std::uint8_t(std::floor(linearToSrgb(linear) * 255.0f + 0.5f)));
}

glm::vec3 asGBufferStoresAlbedo(const glm::vec3& albedo) {
    return {throughSrgb8(albedo.x), throughSrgb8(albedo.y), throughSrgb8(albedo.z)};
}

} // namespace pb::truth
