#pragma once
// Texture layout of one volume's probe data (what the GPU uploads as 2D texture arrays).
//
//   irradiance: width = counts.x * 8, height = counts.z * 8, layers = counts.y, RGBA
//   visibility: width = counts.x * 16, height = counts.z * 16, layers = counts.y, RG
// Probe (x, y, z) owns the tile at texel (x*T, z*T) of layer y (T = 8 or 16): a 1-texel
// border around a 6x6 (14x14) octahedral interior. Texel (col, row, layer) of a C-channel
// texture is at float index ((layer * height + row) * width + col) * C; row 0 comes first,
// exactly as glTexImage3D consumes it.
#include "core/HugePages.h"
#include "probes/ProbeVolume.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pb::probes {

constexpr int kIrradianceInterior = 6;
constexpr int kIrradianceInteriorTexels = kIrradianceInterior * kIrradianceInterior;
constexpr int kIrradianceTile = kIrradianceInterior + 2;
constexpr int kVisibilityInterior = 14;
constexpr int kVisibilityTile = kVisibilityInterior + 2;
constexpr int kIrradianceChannels = 4; // RGB + A (always 1; RGBA16F is the renderable format)
constexpr int kVisibilityChannels = 2; // mean distance, mean squared distance (normalised)

struct TextureShape {
    int width = 0, height = 0, layers = 0, channels = 0;
    std::size_t texelCount() const { return std::size_t(width) * height * layers; }
    std::size_t floatCount() const { return texelCount() * std::size_t(channels); }
    bool operator==(const TextureShape&) const = default;
};

TextureShape irradianceShape(const glm::ivec3& counts);
TextureShape visibilityShape(const glm::ivec3& counts);

// One texture array: `texels` holds the values a GL sampler returns (already quantised to the
// storage format once the bake is finished); `stored` the bytes in the file's format, ready
// for glTexImage3D / glCompressedTexImage3D (filled by quantisation and by the file reader).
// `storageScale` (irradiance only, StorageScale.h): the stored RGB is texels * storageScale, a
// power of two; texels always hold true values.
struct ProbeTexture {
    TextureShape shape;
    // In 2 MiB pages where the kernel allows it (core/HugePages.h): a sparse trial bake's dense
    // textures are tens of MiB written once, and at 4 KiB a page their first touch cost more
    // than the zeroing itself on the 2-core VM. Sized only by make() and assign(), which
    // write every value (the allocator leaves resize()'s new floats unset).
    HugePageVector<float> texels;
    std::vector<std::uint8_t> stored;
    float storageScale = 1.0f;

    // Every texel 0. threads (parallelFor's) > 1: a large texture is zeroed in parallel, so
    // its first-touch page faults (the kernel clearing each page) are taken on all cores.
    static ProbeTexture make(const TextureShape& s, int threads = 1);
    float* at(int col, int row, int layer) {
        return texels.data() + ((std::size_t(layer) * shape.height + row) * shape.width + col) *
                                   std::size_t(shape.channels);
    }
    const float* at(int col, int row, int layer) const {
        return texels.data() + ((std::size_t(layer) * shape.height + row) * shape.width + col) *
                                   std::size_t(shape.channels);
    }
};

// Pointer to texel (0,0) (border included) of probe `c`'s tile.
inline float* tileOrigin(ProbeTexture& t, const glm::ivec3& c, int tile) {
    return t.at(c.x * tile, c.z * tile, c.y);
}
inline const float* tileOrigin(const ProbeTexture& t, const glm::ivec3& c, int tile) {
    return t.at(c.x * tile, c.z * tile, c.y);
}

// Refills every tile's octahedral border from its interior (see Octahedral.h).
void fillAllBorders(ProbeTexture& t, int interior);

} // namespace pb::probes
