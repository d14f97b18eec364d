#include "probes/StorageFormat.h"

#include "core/Error.h"
#include "probes/bc6h/Bc6h.h"

#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

namespace pb::probes {

const char* formatName(StorageFormat f) {
    switch (f) {
    case StorageFormat::Rgba16f:
        return "rgba16f";
    case StorageFormat::Rgba32f:
        return "rgba32f";
    case StorageFormat::Bc6h:
        return "bc6h";
    }
    return "unknown";
}

StorageFormat parseStorageFormat(const std::string& text, const std::string& option) {
    if (text == "rgba16f") return StorageFormat::Rgba16f;
    if (text == "rgba32f") return StorageFormat::Rgba32f;
    if (text == "bc6h") return StorageFormat::Bc6h;
    throw Error(option + ": unknown format '" + text + "' (use rgba16f, rgba32f or bc6h)");
}

bool isKnownFormat(std::uint32_t raw) {
    return raw <= 2;
}

ProbeBytes bytesPerProbe(StorageFormat f) {
    auto bytes = [&](const TextureShape& s) { return storedBytes(s, f); };
    return {bytes(irradianceShape({1, 1, 1})), bytes(visibilityShape({1, 1, 1}))};
}

namespace {
std::size_t bytesPerTexel(int channels, StorageFormat f) {
    // Irradiance is uploaded as 4 channels (RGBA16F/32F), visibility as 2 (RG16F/32F).
    return f == StorageFormat::Rgba32f ? 4u * channels : 2u * channels;
}

float clampForHalf(float v) {
    if (!(v > 0.0f)) return 0.0f; // negatives and NaN
    return v > 65504.0f ? 65504.0f : v;
}

std::size_t layerFloats(const TextureShape& s) {
    return std::size_t(s.width) * s.height * s.channels;
}

// Multiplies the scaled channels (all but an RGBA texture's alpha) by `factor`. A power of two
// times a float is exact, and a factor of 1 is skipped: unscaled textures stay bit for bit.
void scaleTexels(ProbeTexture& t, float factor) {
    if (factor == 1.0f) return;
    const std::size_t channels = std::size_t(t.shape.channels);
    for (std::size_t i = 0; i < t.texels.size(); ++i)
        if (channels != 4 || i % channels != 3) t.texels[i] *= factor;
}
} // namespace

std::size_t storedBytes(const TextureShape& s, StorageFormat f) {
    if (f == StorageFormat::Bc6h) return s.layers * bc6hSizeBytes(s.width, s.height);
    return s.texelCount() * bytesPerTexel(s.channels, f);
}

float quantiseHalf(float v) {
    return glm::unpackHalf1x16(glm::packHalf1x16(clampForHalf(v)));
}

void sanitise(ProbeTexture& t) {
    t.stored.clear();
    scaleTexels(t, t.storageScale); // RGBA32F's scale is 1 (chooseStorageScale): a no-op
    for (float& v : t.texels)
        v = std::isfinite(v) ? v : 0.0f;
}

void quantise(ProbeTexture& t, StorageFormat f) {
    const TextureShape& s = t.shape;
    if (f == StorageFormat::Rgba32f) {
        sanitise(t);
        t.stored.resize(storedBytes(s, f));
        std::memcpy(t.stored.data(), t.texels.data(), t.stored.size());
        return; // decoding would copy the same floats back
    }
    t.stored.assign(storedBytes(s, f), 0);
    scaleTexels(t, t.storageScale);
    if (f == StorageFormat::Rgba16f) {
        for (std::size_t i = 0; i < t.texels.size(); ++i) {
            std::uint16_t h = glm::packHalf1x16(clampForHalf(t.texels[i]));
            std::memcpy(t.stored.data() + 2 * i, &h, 2);
        }
    } else {
        std::size_t layerBytes = bc6hSizeBytes(s.width, s.height);
        for (int l = 0; l < s.layers; ++l) {
            std::vector<float> src(t.texels.begin() + std::ptrdiff_t(l * layerFloats(s)),
                                   t.texels.begin() + std::ptrdiff_t((l + 1) * layerFloats(s)));
            for (float& v : src)
                v = clampForHalf(v);
            std::vector<std::uint8_t> blocks =
                encodeBc6hUf16(src.data(), s.width, s.height, s.channels);
            std::memcpy(t.stored.data() + l * layerBytes, blocks.data(), layerBytes);
        }
    }
    decodeStored(t, f);
}

void decodeStored(ProbeTexture& t, StorageFormat f) {
    const TextureShape& s = t.shape;
    if (t.stored.size() != storedBytes(s, f))
        throw Error("probe texture holds " + std::to_string(t.stored.size()) + " bytes, expected " +
                    std::to_string(storedBytes(s, f)));
    t.texels.assign(s.floatCount(), 0.0f);
    if (f == StorageFormat::Rgba32f) {
        std::memcpy(t.texels.data(), t.stored.data(), t.stored.size());
    } else if (f == StorageFormat::Rgba16f) {
        for (std::size_t i = 0; i < t.texels.size(); ++i) {
            std::uint16_t h;
            std::memcpy(&h, t.stored.data() + 2 * i, 2);
            t.texels[i] = glm::unpackHalf1x16(h);
        }
    } else {
        std::size_t layerBytes = bc6hSizeBytes(s.width, s.height);
        for (int l = 0; l < s.layers; ++l) {
            std::vector<float> rgb =
                decodeBc6hUf16(t.stored.data() + l * layerBytes, s.width, s.height);
            float* dst = t.texels.data() + l * layerFloats(s);
            for (std::size_t i = 0; i < std::size_t(s.width) * s.height; ++i)
                for (int c = 0; c < s.channels; ++c)
                    dst[i * s.channels + c] = c < 3 ? rgb[i * 3 + c] : 1.0f;
        }
    }
    // Only a hand-made file can hold inf/NaN here (the checksum matched): never sample them.
    for (float& v : t.texels)
        v = std::isfinite(v) ? v : 0.0f;
    scaleTexels(t, 1.0f / t.storageScale); // exact: the scale is a power of two
}

} // namespace pb::probes
