#pragma once
// A GI lookup as the texture unit sees it: texel fetches (texelFetch = one texel, texture() =
// the 2x2 GL_LINEAR footprint) on textures laid out in one address space, turned into cache
// line accesses. The probe fetches come from the CPU sampler's trace (ProbeSampler
// SampleTrace), ordered as the variant's loops issue them (GiVariant.h).
#include "costmodel/GiVariant.h"
#include "costmodel/TextureCache.h"
#include "costmodel/TextureMemory.h"
#include "probes/ProbeSampler.h"
#include "probes/store/SparseLayout.h"

#include <cstdint>
#include <vector>

namespace pb::costmodel {

struct Fetch {
    FetchKind kind = FetchKind::GBufferDepth;
    int texture = 0;  // index into TextureTable::textures
    int x = 0, y = 0; // texel (texelFetch) or the footprint's top-left texel (bilinear)
    int layer = 0;
    bool bilinear = false;
    int slot = 0; // the shader instruction that issues it (GiVariant.h fetchSlot)
    // A 3D texture's trilinear fetch (with bilinear): the 2x2 footprints of `layer` and
    // `layer + step.z`, texels x + step.x and y + step.y (a step is 0 where CLAMP_TO_EDGE
    // folds the second texel onto the first).
    bool trilinear = false;
    glm::ivec3 step{1, 1, 1};
};
// Texels a fetch reads as the shader asks: 1 (texelFetch), 4 (bilinear) or 8 (trilinear).
int nominalTexels(const Fetch& f);

// Bytes per texel (or per 4x4 block for BC6H) of the probe textures in a storage format, as
// GpuProbes uploads them: irradiance RGBA16F 8 / RGBA32F 16 / BC6H 16 per block, visibility
// RG16F 4 / RG32F 8 / BC6H 16 per block; the state texture is RGBA32F (16).
struct ProbeTextureFormat {
    int irradianceBytes, visibilityBytes, blockDim;
};
ProbeTextureFormat probeTextureFormat(probes::StorageFormat f);

// The GBuffer textures the apply shader reads and each kept volume's probe textures: DDGI's
// three, or the SH technique's coefficient 3D textures and mask (the others then -1).
struct TextureTable {
    std::vector<TextureMemory> textures;
    int gbufferDepth = 0, gbufferNormal = 1;
    struct Volume {
        int irradiance = -1, visibility = -1, state = -1;
        std::vector<int> sh; // gi.technique=sh_*: coefficient textures (RGBA16F, 8 B)
        int shMask = -1;     // gi.technique=sh_*: R8 validity / mask (1 B)
        // Where each probe's tiles lie in irradiance and visibility, as GpuProbes uploads
        // them: a sparse volume's stored tiles packed (probes/store/SparseLayout.h).
        probes::TileLayout tiles;
    };
    std::vector<Volume> volumes; // by position in the kept list
};
// GBuffer: depth as 4 B/texel (the depth plane of DEPTH32F_STENCIL8; stencil is assumed to
// live in its own plane), normal RG16F 4 B. Probe textures as uploaded: irradiance and
// visibility of the volume's tile grid (sparse: the packed one), the state texture one texel
// per grid probe (a sparse volume's indirection rides in its w). With
// `shCoefficientTextures` > 0 (ShFetchStream.h) the volumes hold the SH technique's textures
// instead, as GpuShTextures uploads them: one texel per grid probe (x, rows z, layers y).
TextureTable makeTextureTable(int gbufferWidth, int gbufferHeight, const probes::ProbeSet& set,
                              const std::vector<int>& keptVolumes, MemoryLayout layout,
                              int shCoefficientTextures = 0);

// Appends one lookup's probe fetches in the order the variant issues them. The trace's texels
// are the dense layout's; they move to the probe's tile in `textures.tiles`. A probe without a
// tile (absent: state w = 0) reads only its state, as in the shader.
void appendProbeFetches(const probes::SampleTrace& trace, const VariantStructure& variant,
                        const TextureTable::Volume& textures, std::vector<Fetch>& out);

// Distinct bytes a fetch reads (its texels, or the distinct 4x4 blocks they fall in).
std::uint64_t footprintBytes(const Fetch& f, const TextureTable& table);

struct CacheStats {
    std::uint64_t probeLines = 0, probeHits = 0; // probe textures (irradiance, visibility, state)
    std::uint64_t gbufferLines = 0, gbufferHits = 0; // the GBuffer reads
};

// One cache replaying one variant's stream.
class CacheReplay {
public:
    CacheReplay(const CacheConfig& config, const TextureTable& table);
    void fetch(const Fetch& f);
    const CacheStats& stats() const { return stats_; }
    const CacheConfig& config() const { return config_; }

private:
    CacheConfig config_;
    LruCache cache_;
    const TextureTable& table_;
    CacheStats stats_;
};

} // namespace pb::costmodel
