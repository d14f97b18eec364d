#include "probes/StorageScale.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {

float maxIrradiance(const std::vector<ProbeTexture>& textures) {
    float m = 0.0f;
    for (const ProbeTexture& t : textures) {
        const std::size_t channels = std::size_t(t.shape.channels);
        for (std::size_t i = 0; i < t.texels.size(); ++i)
            if (i % channels < 3 && std::isfinite(t.texels[i])) m = std::max(m, t.texels[i]);
    }
    return m;
}

float chooseStorageScale(float m, StorageFormat f) {
    if (f == StorageFormat::Rgba32f || !(m > 0.0f) || !std::isfinite(m)) return 1.0f;
    if (m >= kScaleLow && m <= kScaleHigh) return 1.0f;
    // floor(log2(high / m)) in double: exact for the float m, no rounding at the boundaries.
    int e = int(std::floor(std::log2(double(kScaleHigh) / double(m))));
    e = std::clamp(e, -kMaxScaleExponent, kMaxScaleExponent);
    return std::ldexp(1.0f, e);
}

bool isValidStorageScale(float s) {
    if (!std::isfinite(s) || !(s > 0.0f)) return false;
    int e = 0;
    const float mantissa = std::frexp(s, &e); // s = mantissa * 2^e, mantissa in [0.5, 1)
    return mantissa == 0.5f && std::abs(e - 1) <= kMaxScaleExponent;
}

void assignStorageScale(std::vector<ProbeTexture>& scenarioTextures, StorageFormat f) {
    // RGBA32F is never scaled (chooseStorageScale): no pass over every texel for its maximum.
    const float s =
        f == StorageFormat::Rgba32f ? 1.0f : chooseStorageScale(maxIrradiance(scenarioTextures), f);
    for (ProbeTexture& t : scenarioTextures)
        t.storageScale = s;
}

} // namespace pb::probes
