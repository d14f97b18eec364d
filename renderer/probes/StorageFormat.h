#pragma once
// How probe textures are stored in the file and on the GPU, what that costs, and the
// quantisation the sampler must see (it samples the values the GPU would decode).
//
//   rgba16f: irradiance GL_RGBA16F (8 B/texel), visibility GL_RG16F (4 B/texel)  [default]
//   rgba32f: irradiance GL_RGBA32F (16 B/texel), visibility GL_RG32F (8 B/texel)
//   bc6h:    both GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT (16 B per 4x4 block = 1 B/texel);
//            visibility in R,G with B = 0; irradiance alpha reads back as 1.
// Half floats: values are clamped to [0, 65504] and NaN becomes 0 before packing (BC6H
// unsigned does the same), so no texel is ever inf/NaN.
#include "probes/ProbeLayout.h"

#include <cstdint>
#include <string>

namespace pb::probes {

enum class StorageFormat : std::uint32_t { Rgba16f = 0, Rgba32f = 1, Bc6h = 2 };

const char* formatName(StorageFormat f);
// "rgba16f" | "rgba32f" | "bc6h"; throws pb::Error naming `option` otherwise.
StorageFormat parseStorageFormat(const std::string& text, const std::string& option = "--format");
bool isKnownFormat(std::uint32_t raw);

struct ProbeBytes {
    std::size_t irradiance = 0, visibility = 0;
    std::size_t total() const { return irradiance + visibility; }
};
// Bytes per probe (border texels included): rgba16f 512 + 1024, rgba32f 1024 + 2048,
// bc6h 64 + 256 - the reference talk's figures.
ProbeBytes bytesPerProbe(StorageFormat f);
std::size_t storedBytes(const TextureShape& s, StorageFormat f);

// Encodes t.texels * t.storageScale (RGB; alpha unscaled) into t.stored in format `f`, then
// replaces t.texels by the decoded values divided by the scale (what GL samples, times
// 1 / storageScale: the true values). Deterministic; with scale 1 exactly as without one.
void quantise(ProbeTexture& t, StorageFormat f);
// The texels quantise(t, Rgba32f) leaves, without the stored bytes (left empty): non-finite
// values become 0. For sets read only on the CPU (the lattice search's trial bakes).
void sanitise(ProbeTexture& t);
// Fills t.texels from t.stored (t.shape and t.storageScale set). Throws pb::Error when the
// size is wrong.
void decodeStored(ProbeTexture& t, StorageFormat f);

// Half-float round trip of one value with the clamping above (what RGBA16F stores).
float quantiseHalf(float v);

} // namespace pb::probes
