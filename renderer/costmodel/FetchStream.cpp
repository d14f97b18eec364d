#include "costmodel/FetchStream.h"

#include "probes/AbsentProbeFill.h"

#include <algorithm>

namespace pb::costmodel {

ProbeTextureFormat probeTextureFormat(probes::StorageFormat f) {
    switch (f) {
    case probes::StorageFormat::Rgba32f:
        return {16, 8, 1};
    case probes::StorageFormat::Bc6h:
        return {16, 16, 4};
    case probes::StorageFormat::Rgba16f:
        break;
    }
    return {8, 4, 1};
}

TextureTable makeTextureTable(int gbufferWidth, int gbufferHeight, const probes::ProbeSet& set,
                              const std::vector<int>& keptVolumes, MemoryLayout layout,
                              int shCoefficientTextures) {
    TextureTable t;
    std::uint64_t next = kTextureAlignment; // address 0 left unused
    auto add = [&](int w, int h, int layers, int block, int bytes, bool volume = false) {
        t.textures.emplace_back(next, w, h, layers, block, bytes, layout, volume);
        next = t.textures.back().end();
        return int(t.textures.size()) - 1;
    };
    t.gbufferDepth = add(gbufferWidth, gbufferHeight, 1, 1, 4);
    t.gbufferNormal = add(gbufferWidth, gbufferHeight, 1, 1, 4);
    const ProbeTextureFormat fmt = probeTextureFormat(set.format());
    for (int v : keptVolumes) {
        const probes::ProbeVolume& volume = set.volumes[size_t(v)];
        const glm::ivec3 n = volume.counts;
        TextureTable::Volume vol;
        if (shCoefficientTextures > 0) {
            for (int k = 0; k < shCoefficientTextures; ++k)
                vol.sh.push_back(add(n.x, n.z, n.y, 1, 8, true));
            vol.shMask = add(n.x, n.z, n.y, 1, 1, true);
            t.volumes.push_back(vol);
            continue;
        }
        vol.tiles = probes::tileLayout(
            volume, set.states[size_t(v)],
            probes::fillSources(volume, set.states[size_t(v)], set.settings.backfaceThreshold));
        const probes::TextureShape irr = probes::irradianceShape(vol.tiles.packedCounts);
        const probes::TextureShape vis =
            probes::visibilityShape(vol.tiles.visibilityPackedCounts);
        vol.irradiance = add(irr.width, irr.height, irr.layers, fmt.blockDim, fmt.irradianceBytes);
        vol.visibility = add(vis.width, vis.height, vis.layers, fmt.blockDim, fmt.visibilityBytes);
        vol.state = add(n.x, n.z, n.y, 1, 16); // texel (i, k) of layer j, like the tiles
        t.volumes.push_back(vol);
    }
    return t;
}

void appendProbeFetches(const probes::SampleTrace& trace, const VariantStructure& variant,
                        const TextureTable::Volume& tex, std::vector<Fetch>& out) {
    if (!trace.probesRead) return;
    for (size_t loop = 0; loop < variant.loops.size(); ++loop)
        for (int step = 0; step < kProbesPerLookup; ++step) {
            const probes::CornerFetch& c =
                trace.corners[samplerCorner(variant.cornerOffsets[size_t(step)])];
            if (!c.inGrid) continue;
            // The trace's texels sit in the dense tile (probe.x, probe.z) of layer probe.y.
            const glm::ivec3 tile = tex.tiles.tileOf(c.probe);
            const glm::ivec2 denseTile(c.probe.x, c.probe.z);
            const glm::ivec2 vis =
                c.visTexel + (glm::ivec2(tile) - denseTile) * probes::kVisibilityTile;
            const glm::ivec2 irr =
                c.irradianceTexel + (glm::ivec2(tile) - denseTile) * probes::kIrradianceTile;
            const std::vector<FetchKind>& kinds = variant.loops[loop];
            for (size_t k = 0; k < kinds.size(); ++k) {
                const int slot = fetchSlot(variant, int(loop), step, int(k));
                if (kinds[k] == FetchKind::ProbeState) {
                    out.push_back(
                        {kinds[k], tex.state, c.probe.x, c.probe.z, c.probe.y, false, slot});
                    continue;
                }
                // The shader's weight < 0 (invalid or absent): no further fetch of this probe.
                if (!c.valid || tile.z < 0) break;
                // An irradiance-only probe's tile lies past the visibility texture's layers:
                // the shader's fetch still runs (its result unused) and GL clamps the layer.
                if (kinds[k] == FetchKind::Visibility)
                    out.push_back({kinds[k], tex.visibility, vis.x, vis.y,
                                   std::min(tile.z, tex.tiles.visibilityPackedCounts.y - 1), true,
                                   slot});
                else if (kinds[k] == FetchKind::Irradiance)
                    out.push_back({kinds[k], tex.irradiance, irr.x, irr.y, tile.z, true, slot});
            }
        }
}

namespace {
// The distinct addresses of a fetch's texels, or of the blocks holding them.
constexpr int kMaxTexels = 8;
int fetchAddresses(const Fetch& f, const TextureMemory& m, std::uint64_t out[kMaxTexels]) {
    if (!f.bilinear) {
        out[0] = m.address(f.x, f.y, f.layer);
        return 1;
    }
    const glm::ivec3 step = f.trilinear ? f.step : glm::ivec3(1, 1, 0);
    int n = 0;
    for (int dz = 0; dz < (f.trilinear ? 2 : 1); ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const std::uint64_t a =
                    m.address(f.x + dx * step.x, f.y + dy * step.y, f.layer + dz * step.z);
                if (std::find(out, out + n, a) == out + n) out[n++] = a;
            }
    return n;
}
} // namespace

int nominalTexels(const Fetch& f) {
    return !f.bilinear ? 1 : f.trilinear ? 8 : 4;
}

std::uint64_t footprintBytes(const Fetch& f, const TextureTable& table) {
    const TextureMemory& m = table.textures[size_t(f.texture)];
    std::uint64_t a[kMaxTexels];
    return std::uint64_t(fetchAddresses(f, m, a)) * std::uint64_t(m.elementBytes());
}

CacheReplay::CacheReplay(const CacheConfig& config, const TextureTable& table)
    : config_(config), cache_(config), table_(table) {}

void CacheReplay::fetch(const Fetch& f) {
    std::uint64_t addr[kMaxTexels];
    const int n = fetchAddresses(f, table_.textures[size_t(f.texture)], addr);
    // A fetch asks for each line it touches once (the texture unit merges a footprint).
    const std::uint64_t lineMask = ~std::uint64_t(config_.lineBytes - 1);
    std::uint64_t lines[kMaxTexels];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const std::uint64_t l = addr[i] & lineMask;
        if (std::find(lines, lines + m, l) == lines + m) lines[m++] = l;
    }
    const bool gbuffer = f.kind == FetchKind::GBufferDepth || f.kind == FetchKind::GBufferNormal;
    for (int i = 0; i < m; ++i) {
        const bool hit = cache_.access(lines[i]);
        if (gbuffer) {
            ++stats_.gbufferLines;
            stats_.gbufferHits += hit;
        } else {
            ++stats_.probeLines;
            stats_.probeHits += hit;
        }
    }
}

} // namespace pb::costmodel
