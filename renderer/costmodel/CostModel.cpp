#include "costmodel/CostModel.h"

#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "costmodel/FetchStream.h"
#include "profile/GiVolumeLod.h"
#include "costmodel/PixelOrder.h"
#include "core/ParallelFor.h"
#include "probes/ProbeSampler.h"

#include <algorithm>

namespace pb::costmodel {

namespace {

constexpr int kGBufferTexturesBound = 5; // passes/GBufferLayout.h: 4 channels + depth
constexpr int kUnitsUnbound = 8;         // GiApplyPass: units 0 .. kFirstProbeUnit + 2
constexpr std::size_t kChunkMin = 4096;  // pixels traced per step (bounds memory)

int targetBytes(profile::GiTargetFormat f) {
    switch (f) {
    case profile::GiTargetFormat::Rgba32f:
        return 16;
    case profile::GiTargetFormat::R11g11b10f:
        return 4;
    case profile::GiTargetFormat::Rgba16f:
        break;
    }
    return 8;
}

// What one pixel of one volume's draw did. Skipped: no fragment of the apply draw (stencil:
// the pixel is sky, outside the influence or taken by a smaller volume - the fill pass and the
// stencil test, not modelled fragment by fragment, kept it out).
struct Lookup {
    enum Stage : std::uint8_t { Skipped, Sky, Outside, Evaluated } stage = Sky;
    probes::SampleTrace trace;
};

void countLookup(const Lookup& l, const std::vector<Fetch>& fetches, const TextureTable& table,
                 bool shFlags, VolumeCounters& c) {
    if (l.stage == Lookup::Skipped) return;
    ++c.fragments;
    ++c.depthFetches;
    if (l.stage == Lookup::Sky) {
        ++c.skySkipped;
        return;
    }
    c.flagsFetches += shFlags; // gi_ddgi_apply.frag: the SH early-out before the influence test
    if (l.stage == Lookup::Outside) {
        ++c.outsideSkipped;
        return;
    }
    ++c.normalFetches;
    ++c.evaluated;
    if (!l.trace.probesRead) ++c.fadedOut;
    for (const Fetch& f : fetches) {
        c.stateFetches += f.kind == FetchKind::ProbeState;
        c.visibilityFetches += f.kind == FetchKind::Visibility;
        c.irradianceFetches += f.kind == FetchKind::Irradiance;
        c.probeFootprintBytes += footprintBytes(f, table);
    }
}

} // namespace

double CacheResult::probeHitRate() const {
    return probeLines ? double(probeHits) / double(probeLines) : 0.0;
}
double CacheResult::probeBytesMissedPerPixel(std::uint64_t giPixels) const {
    return giPixels ? double(probeLines - probeHits) * cache.lineBytes / double(giPixels) : 0.0;
}
double CacheResult::allBytesMissedPerPixel(std::uint64_t giPixels) const {
    const std::uint64_t misses = probeLines - probeHits + gbufferLines - gbufferHits;
    return giPixels ? double(misses) * cache.lineBytes / double(giPixels) : 0.0;
}

// Replays `n` lookups through one cache as SIMT groups issue them: per group of
// warpsInFlight warps, instruction slot by slot, warp by warp, pixel by pixel.
void replayChunk(CacheReplay& replay, const VariantStructure& vs, const TextureTable& table,
                 const TextureTable::Volume& tex, const Lookup* lookups,
                 const glm::ivec2* gbufferPx, size_t n, int warpPixels, int warpsInFlight) {
    const size_t group = size_t(warpPixels) * size_t(warpsInFlight);
    const int slots = fetchSlotCount(vs);
    std::vector<std::vector<Fetch>> pixel(group);
    std::vector<size_t> next(group);
    for (size_t g = 0; g < n; g += group) {
        const size_t m = std::min(group, n - g);
        for (size_t i = 0; i < m; ++i) {
            std::vector<Fetch>& f = pixel[i];
            f.clear();
            next[i] = 0;
            if (lookups[g + i].stage == Lookup::Skipped) continue;
            const glm::ivec2 px = gbufferPx[g + i];
            f.push_back({FetchKind::GBufferDepth, table.gbufferDepth, px.x, px.y, 0, false, 0});
            if (lookups[g + i].stage == Lookup::Evaluated) {
                f.push_back(
                    {FetchKind::GBufferNormal, table.gbufferNormal, px.x, px.y, 0, false, 1});
                appendProbeFetches(lookups[g + i].trace, vs, tex, f);
            }
        }
        // Warps interleave per instruction (slot); inside a warp, pixels in order.
        for (int s = 0; s < slots; ++s)
            for (size_t i = 0; i < m; ++i)
                while (next[i] < pixel[i].size() && pixel[i][next[i]].slot == s)
                    replay.fetch(pixel[i][next[i]++]);
    }
}

CostReport runCostModel(const views::CoverageTester& tester, const scene::View& view,
                        const CostModelOptions& o) {
    if (o.width < 1 || o.height < 1) throw Error("cost model: resolution must be at least 1x1");
    if (o.warpPixels < 1 || o.warpPixels > 1024 || o.warpsInFlight < 1 || o.warpsInFlight > 256)
        throw Error("cost model: warp size must be in 1..1024 and warps in flight in 1..256");
    const size_t group = size_t(o.warpPixels) * size_t(o.warpsInFlight);
    const size_t kChunk = (kChunkMin + group - 1) / group * group;
    const probes::ProbeSet& set = tester.probes();
    if (o.scenario < 0 || o.scenario >= int(set.irradiance.size()))
        throw Error("cost model: the probe set has no scenario #" + std::to_string(o.scenario));
    const std::vector<CacheConfig> caches = o.caches.empty() ? cachePresets() : o.caches;
    for (const CacheConfig& c : caches)
        c.validate();

    CostReport r;
    r.profile = o.profile;
    r.probeFormat = probes::formatName(set.format());
    r.layout = layoutName(o.layout);
    r.tile = o.tile;
    r.warpPixels = o.warpPixels;
    r.warpsInFlight = o.warpsInFlight;
    r.profileVariant = GiVariant{o.profile.gi.probeOrder, o.profile.gi.loops}.name();

    // The pass: kept volumes in draw order, the GI target and its pixels in shading order.
    const std::vector<int> kept =
        profile::selectVolumes(set, profile::parseVolumeLod(o.profile.gi.volumeLod));
    std::vector<float> boxes;
    for (int v : kept)
        boxes.push_back(set.volumes[size_t(v)].boxVolume());
    std::vector<int> drawOrder = profile::volumeDrawOrder(boxes, kept); // largest first
    const bool stencil = o.profile.gi.multiVolume == profile::GiMultiVolume::Stencil;
    const bool shFlags = o.profile.gi.dynamic == profile::GiDynamic::Sh;
    if (stencil) std::reverse(drawOrder.begin(), drawOrder.end()); // smallest first
    GiPassCounters& c = r.counters;
    c.multiVolume = o.profile.get("gi.multi_volume");
    c.gbufferWidth = o.width;
    c.gbufferHeight = o.height;
    c.divisor = profile::resolutionDivisor(o.profile.gi.resolution);
    c.targetWidth = std::max(1, o.width / c.divisor);
    c.targetHeight = std::max(1, o.height / c.divisor);
    c.targetFormat = o.profile.get("gi.target_format");
    c.targetBytesPerPixel = targetBytes(o.profile.gi.targetFormat);
    c.targetPixels = std::uint64_t(c.targetWidth) * std::uint64_t(c.targetHeight);
    const std::vector<glm::ivec2> order = gpuPixelOrder(c.targetWidth, c.targetHeight, o.tile);

    // gi_ddgi_apply.frag reads GBuffer pixel fragCoord * divisor + (divisor - 1) / 2 (GL rows
    // count from the bottom; the rays' rows from the top).
    std::vector<glm::ivec2> rayPixels(order.size()), gbufferPx(order.size());
    for (size_t i = 0; i < order.size(); ++i) {
        gbufferPx[i] = order[i] * c.divisor + (c.divisor - 1) / 2;
        rayPixels[i] = {gbufferPx[i].x, o.height - 1 - gbufferPx[i].y};
    }
    const std::vector<views::SurfacePoint> surface =
        tester.surfacePoints(view, o.width, o.height, rayPixels);
    const probes::ProbeSampler sampler(set, o.scenario);
    const TextureTable table = makeTextureTable(o.width, o.height, set, kept, o.layout);

    const std::vector<GiVariant> variants = allGiVariants();
    std::vector<VariantStructure> structures;
    for (const GiVariant& v : variants)
        structures.push_back(variantStructure(v));
    std::vector<CacheReplay> replays; // variant-major: variants x caches
    replays.reserve(variants.size() * caches.size());
    for (size_t v = 0; v < variants.size(); ++v)
        for (const CacheConfig& cfg : caches)
            replays.emplace_back(cfg, table);

    std::vector<std::uint8_t> covered(order.size(), 0); // stencil: 'any' set
    std::vector<int> winner(order.size(), -1);
    std::vector<Lookup> lookups(kChunk);
    int drawn = 0;
    for (int d : drawOrder) {
        const int fileIndex = kept[size_t(d)];
        VolumeCounters vc;
        vc.name = set.volumes[size_t(fileIndex)].name;
        vc.fileIndex = fileIndex;
        vc.culled = std::find(o.culledVolumes.begin(), o.culledVolumes.end(), fileIndex) !=
                    o.culledVolumes.end();
        if (vc.culled) {
            c.volumes.push_back(vc);
            continue;
        }
        ++drawn;
        const TextureTable::Volume& tex = table.volumes[size_t(d)];
        for (size_t start = 0; start < order.size(); start += kChunk) {
            const size_t n = std::min(kChunk, order.size() - start);
            // 1. The lookups of this chunk (parallel: one slot each).
            pb::parallelFor(n, 0, [&](size_t i, int) {
                const views::SurfacePoint& s = surface[start + i];
                Lookup& l = lookups[i];
                const Lookup::Stage miss = stencil ? Lookup::Skipped : Lookup::Outside;
                l.stage = !s.hit                                           ? Lookup::Sky
                          : stencil && covered[start + i]                  ? Lookup::Skipped
                          : sampler.influencesPoint(fileIndex, s.position) ? Lookup::Evaluated
                                                                           : miss;
                if (stencil && l.stage == Lookup::Sky) l.stage = Lookup::Skipped;
                if (l.stage == Lookup::Evaluated)
                    sampler.sampleVolume(fileIndex, s.position, s.normal,
                                         view.position - s.position, {}, &l.trace);
            });
            // 2. Counters (the fetches are the same set in every variant: count the first).
            std::vector<Fetch> fetches;
            for (size_t i = 0; i < n; ++i) {
                fetches.clear();
                if (lookups[i].stage == Lookup::Evaluated) {
                    appendProbeFetches(lookups[i].trace, structures[0], tex, fetches);
                    covered[start + i] = 1;
                    winner[start + i] = d;
                }
                countLookup(lookups[i], fetches, table, shFlags, vc);
            }
            // 3. Every (variant, cache) replays the chunk in shading order (parallel: each
            //    replay owns its cache).
            pb::parallelFor(replays.size(), 0, [&](size_t k, int) {
                replayChunk(replays[k], structures[k / caches.size()], table, tex, lookups.data(),
                            gbufferPx.data() + start, n, o.warpPixels, o.warpsInFlight);
            });
        }
        c.volumes.push_back(vc);
    }

    // Totals.
    for (size_t i = 0; i < order.size(); ++i) {
        c.giPixels += covered[i];
        if (winner[i] >= 0)
            for (size_t k = 0; k < drawOrder.size(); ++k)
                if (drawOrder[k] == winner[i]) ++c.volumes[k].won;
    }
    if (stencil) {
        c.drawCalls = c.programBinds = c.textureBinds = c.textureUnbinds = -1;
        c.depthCopyFetches = c.targetPixels; // gi_depth_copy.frag: one depth read per texel
    } else {
        c.drawCalls = drawn;
        c.textureBinds = kGBufferTexturesBound + 3 * drawn;
        c.textureUnbinds = 2 * kUnitsUnbound;
    }
    c.gbufferFetches = c.depthCopyFetches;
    for (const VolumeCounters& v : c.volumes) {
        c.gbufferFetches += v.depthFetches + v.normalFetches + v.flagsFetches;
        c.probeFetches += v.stateFetches + v.visibilityFetches + v.irradianceFetches;
        c.probeFootprintBytes += v.probeFootprintBytes;
        c.renderTargetBytesWritten += v.evaluated * std::uint64_t(c.targetBytesPerPixel);
    }
    c.fetchesPerGiPixel =
        c.giPixels ? double(c.gbufferFetches + c.probeFetches) / double(c.giPixels) : 0.0;
    c.maxFetchesPerLookup =
        maxFetchesPerLookup(GiVariant{o.profile.gi.probeOrder, o.profile.gi.loops});
    c.clearBytes = c.targetPixels * std::uint64_t(c.targetBytesPerPixel);
    for (int v : kept)
        c.gpuProbeBytes += profile::gpuVolumeBytes(set, size_t(v));

    for (size_t k = 0; k < replays.size(); ++k) {
        CacheResult res;
        res.variant = variants[k / caches.size()].name();
        res.cache = caches[k % caches.size()];
        const CacheStats& s = replays[k].stats();
        res.probeLines = s.probeLines;
        res.probeHits = s.probeHits;
        res.gbufferLines = s.gbufferLines;
        res.gbufferHits = s.gbufferHits;
        r.results.push_back(res);
    }
    return r;
}

} // namespace pb::costmodel
