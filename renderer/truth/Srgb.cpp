#include "truth/Srgb.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pb::truth {

float linearToSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgb8ToLinear(std::uint8_t code) {
    static const std::array<float, 256> lut = [] {
        std::array<float, 256> l{};
        for (int i = 0; i < 256; ++i) {
            const float c = float(i) / 255.0f;
            l[std::size_t(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
        return l;
    }();
    return lut[code];
}

} // namespace pb::truth
