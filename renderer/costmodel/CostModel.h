#pragma once
// The deterministic cost model of the GI apply pass (issue 7, items 1 and 2): for a scene,
// probe set, view and profile it replays what the pass does on a GPU - per kept volume not
// culled, gi.multi_volume=naive: one full-screen draw (largest first) with the sky and influence
// discards; =stencil: each pixel evaluated once, by the smallest volume containing it - per
// pixel of the GI target the GBuffer reads (+ the flags with gi.dynamic=sh) and the 8-probe
// lookup of common_ddgi.glsl, or with gi.technique=sh_l1|sh_l2 the SH lookup of common_sh.glsl
// (ShFetchStream.h; its one "variant" is named after the technique and leak mode) - on the CPU:
//   - exact counters (pixels per volume, fetches by kind, footprint bytes, render-target
//     bytes, draws and binds, GPU memory of the probe data): hardware-independent;
//   - each shader variant's texel-address stream through set-associative LRU caches: hit
//     rate and bytes missed per pixel, per variant and cache.
// Surface points come from CPU primary rays (views::CoverageTester::surfacePoints), the probe
// texels from the CPU sampler's own arithmetic (probes::SampleTrace). GL-free, deterministic
// for any thread count.
#include "costmodel/GiVariant.h"
#include "costmodel/TextureCache.h"
#include "costmodel/TextureMemory.h"
#include "profile/Profile.h"
#include "views/WorstCaseView.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pb::costmodel {

struct CostModelOptions {
    int width = 1280, height = 720; // GBuffer (the frame); the GI target follows gi.resolution
    profile::Profile profile;       // gi.resolution, gi.target_format, gi.volume_lod; the
                                    // report marks the profile's own variant
    int scenario = 0;
    std::vector<CacheConfig> caches; // empty: every preset
    MemoryLayout layout = MemoryLayout::Tiled;
    int tile = 8; // pixel tile of the shading order (PixelOrder.h)
    // SIMT issue: consecutive pixels form a warp (wave) that issues each fetch instruction
    // for all its pixels before the next; warpsInFlight warps take turns per instruction
    // through the same cache. 1 and 1 = one pixel after the other.
    int warpPixels = 32;
    int warpsInFlight = 4;
    // File indices of volumes the pass culls (outside the view frustum: GiApplyPass::stats()
    // says which); empty: none culled. A culled volume is not drawn: no fragment, no fetch.
    std::vector<int> culledVolumes;
};

struct VolumeCounters {
    std::string name;
    int fileIndex = 0;
    std::uint64_t fragments = 0;      // the draw's fragments: every target pixel
    std::uint64_t skySkipped = 0;     // discarded: depth = far plane
    std::uint64_t outsideSkipped = 0; // discarded: outside the volume's influence
    std::uint64_t evaluated = 0;      // ran the lookup (and wrote the target)
    std::uint64_t fadedOut = 0;       // of those: edge fade 0, returned before any probe
    std::uint64_t won = 0;            // pixels whose final value is this volume's
    bool culled = false;
    std::uint64_t depthFetches = 0, normalFetches = 0;
    std::uint64_t flagsFetches = 0; // gi.dynamic=sh: the early-out's flags read
    std::uint64_t stateFetches = 0, visibilityFetches = 0, irradianceFetches = 0;
    std::uint64_t shMaskFetches = 0, shCoefficientFetches = 0; // gi.technique=sh_*
    std::uint64_t probeTexels = 0;         // texels its probe fetches ask for (1, 4 or 8 each)
    std::uint64_t probeFootprintBytes = 0; // distinct texel (block) bytes of its probe fetches
};

struct GiPassCounters {
    std::string multiVolume; // gi.multi_volume
    int gbufferWidth = 0, gbufferHeight = 0, targetWidth = 0, targetHeight = 0, divisor = 1;
    std::string targetFormat;
    int targetBytesPerPixel = 0;
    std::uint64_t targetPixels = 0;
    std::uint64_t giPixels = 0; // target pixels evaluated by at least one volume
    // Pass structure of gi.multi_volume=naive (passes/GiApplyPass.cpp): one clear, one
    // program, the GBuffer's 5 textures (4 channels + depth) once, 3 textures and one draw per
    // drawn volume, then units 0..7 unbound for 2D and 2D-array targets. -1 for stencil (depth
    // copy, fill and box draws depend on the eye's position: `probebench gate` counts the GL
    // calls of the real pass instead).
    int drawCalls = 0, clears = 1, programBinds = 1, textureBinds = 0, textureUnbinds = 0;
    std::uint64_t gbufferFetches = 0, probeFetches = 0; // gbuffer: apply + depth copy
    std::uint64_t depthCopyFetches = 0; // stencil: the GI depth copy, one per target pixel
    double fetchesPerGiPixel = 0;
    int maxFetchesPerLookup = 0; // the shader's structure: GBuffer + 8 probes x fetches
    std::uint64_t probeFootprintBytes = 0;
    std::uint64_t probeTexels = 0;
    std::uint64_t renderTargetBytesWritten = 0; // evaluated fragments x target bytes
    std::uint64_t clearBytes = 0;               // target pixels x target bytes
    std::uint64_t gpuProbeBytes = 0;            // profile::gpuVolumeBytes of the kept volumes
    std::vector<VolumeCounters> volumes;        // in draw order
};

struct CacheResult {
    std::string variant;
    CacheConfig cache;
    std::uint64_t probeLines = 0, probeHits = 0, gbufferLines = 0, gbufferHits = 0;
    double probeHitRate() const;
    double probeBytesMissedPerPixel(std::uint64_t giPixels) const;
    double allBytesMissedPerPixel(std::uint64_t giPixels) const;
};

struct CostReport {
    std::string scene, view, camera, probeFormat, layout;
    std::string profileVariant; // the variant the profile selects
    int tile = 8, warpPixels = 32, warpsInFlight = 4;
    profile::Profile profile;
    GiPassCounters counters;
    std::vector<CacheResult> results; // variants x caches, variant-major
};

CostReport runCostModel(const views::CoverageTester& tester, const scene::View& view,
                        const CostModelOptions& options);

nlohmann::json reportJson(const CostReport& r);
// The readable table (variants x caches) and the counters.
std::string reportText(const CostReport& r);

} // namespace pb::costmodel
