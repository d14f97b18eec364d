#include "costmodel/CostModel.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "costmodel/CachePresets.h"
#include "costmodel/FetchStream.h"
#include "costmodel/PixelOrder.h"
#include "costmodel/ShFetchStream.h"
#include "probes/ProbeSampler.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/sh/ShSampler.h"
#include "profile/GiDynamicReads.h"
#include "profile/GiVolumeLod.h"

#include <algorithm>
#include <optional>

namespace pb::costmodel {

namespace {

constexpr int kGBufferTexturesBound = 5; // passes/GBufferLayout.h: 4 channels + depth
constexpr int kUnitsUnbound = 8;         // GiApplyPass: units 0 .. kFirstProbeUnit + 2
constexpr int kShUnitsBound = 8;         // passes/GpuTechniqueSh.h kShUnitsPerVolume
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

// What one pixel of one volume's draw did. Skipped: no lookup of the apply draw counted
// (stencil: the pixel is sky, outside the influence or taken by a smaller volume; the depth
// reads of the fragments the influence test discards are not modelled, README.md).
struct Lookup {
    enum Stage : std::uint8_t { Skipped, Sky, Outside, Evaluated } stage = Sky;
    probes::SampleTrace trace; // DDGI
    probes::ShTrace sh;        // gi.technique=sh_*
};

void countLookup(const Lookup& l, const std::vector<Fetch>& fetches, const TextureTable& table,
                 bool flagsRead, VolumeCounters& c) {
    if (l.stage == Lookup::Skipped) return;
    ++c.fragments;
    ++c.depthFetches;
    if (l.stage == Lookup::Sky) {
        ++c.skySkipped;
        return;
    }
    // gi_ddgi_apply.frag, before the influence test: the SH early-out (GI_DYNAMIC_SH) or the
    // dynamic pixels' unfaded lookup (GI_DYNAMIC_UNFADED).
    c.flagsFetches += flagsRead;
    if (l.stage == Lookup::Outside) {
        ++c.outsideSkipped;
        return;
    }
    ++c.normalFetches;
    ++c.evaluated;
    if (!l.trace.probesRead && !l.sh.maskRead && !l.sh.coefficientsRead) ++c.fadedOut;
    for (const Fetch& f : fetches) {
        c.stateFetches += f.kind == FetchKind::ProbeState;
        c.visibilityFetches += f.kind == FetchKind::Visibility;
        c.irradianceFetches += f.kind == FetchKind::Irradiance;
        c.shMaskFetches += f.kind == FetchKind::ShMask;
        c.shCoefficientFetches += f.kind == FetchKind::ShCoefficients;
        c.probeTexels += std::uint64_t(nominalTexels(f));
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

// One lookup's probe fetches: the DDGI variant's (`vs`) or, without one, the SH technique's.
void appendLookupFetches(const Lookup& l, const VariantStructure* vs,
                         const TextureTable::Volume& tex, const glm::ivec3& counts,
                         std::vector<Fetch>& out) {
    if (vs)
        appendProbeFetches(l.trace, *vs, tex, out);
    else
        appendShFetches(l.sh, tex, counts, out);
}

// Replays `n` lookups through one cache as SIMT groups issue them: per group of
// warpsInFlight warps, instruction slot by slot, warp by warp, pixel by pixel. `vs`: the DDGI
// variant; null: the SH technique (ShFetchStream.h) on a volume of `counts` probes.
void replayChunk(CacheReplay& replay, const VariantStructure* vs, const TextureTable& table,
                 const TextureTable::Volume& tex, const glm::ivec3& counts, const Lookup* lookups,
                 const glm::ivec2* gbufferPx, size_t n, int warpPixels, int warpsInFlight) {
    const size_t group = size_t(warpPixels) * size_t(warpsInFlight);
    const int slots = vs ? fetchSlotCount(*vs) : shFetchSlotCount(int(tex.sh.size()));
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
                appendLookupFetches(lookups[g + i], vs, tex, counts, f);
            }
        }
        // Warps interleave per instruction (slot); inside a warp, pixels in order.
        for (int s = 0; s < slots; ++s)
            for (size_t i = 0; i < m; ++i)
                while (next[i] < pixel[i].size() && pixel[i][next[i]].slot == s)
                    replay.fetch(pixel[i][next[i]++]);
    }
}

namespace {

// The SH technique's one fetch stream, named by technique and leak mode ("sh_l1/weight").
std::string shVariantName(const profile::Profile& p) {
    return p.get("gi.technique") + "/" + p.get("gi.sh_leak");
}

// The report's header: what was modelled.
CostReport describeRun(const CostModelOptions& o, const probes::ProbeSet& set) {
    CostReport r;
    r.profile = o.profile;
    r.probeFormat = probes::formatName(set.format());
    r.layout = layoutName(o.layout);
    r.tile = o.tile;
    r.warpPixels = o.warpPixels;
    r.warpsInFlight = o.warpsInFlight;
    r.profileVariant = shCoefficientTextures(o.profile.gi.technique) > 0
                           ? shVariantName(o.profile)
                           : GiVariant{o.profile.gi.probeOrder, o.profile.gi.loops}.name();
    return r;
}

// The GI target's size and format, as GiTargets allocates it.
void describeTarget(const CostModelOptions& o, GiPassCounters& c) {
    c.multiVolume = o.profile.get("gi.multi_volume");
    c.gbufferWidth = o.width;
    c.gbufferHeight = o.height;
    c.divisor = profile::resolutionDivisor(o.profile.gi.resolution);
    c.targetWidth = std::max(1, o.width / c.divisor);
    c.targetHeight = std::max(1, o.height / c.divisor);
    c.targetFormat = o.profile.get("gi.target_format");
    c.targetBytesPerPixel = targetBytes(o.profile.gi.targetFormat);
    c.targetPixels = std::uint64_t(c.targetWidth) * std::uint64_t(c.targetHeight);
}

// One run of the model as the pass's steps: the kept volumes in draw order, the target's
// pixels in shading order and their surface points, then per volume and chunk of pixels the
// lookups, their counters and every (variant, cache) replay, then the totals.
class CostModelRun {
public:
    CostModelRun(const views::CoverageTester& tester, const scene::View& view,
                 const CostModelOptions& o, const std::vector<CacheConfig>& caches,
                 GiPassCounters& c)
        : view_(view), o_(o), set_(tester.probes()), caches_(caches), c_(c),
          kept_(profile::selectVolumes(set_, profile::parseVolumeLod(o.profile.gi.volumeLod))),
          stencil_(o.profile.gi.multiVolume == profile::GiMultiVolume::Stencil),
          flagsRead_(profile::applyReadsFlags(o.profile, tester.hasDynamicObjects())),
          shTextures_(shCoefficientTextures(o.profile.gi.technique)), sampler_(set_, o.scenario),
          table_(makeTextureTable(o.width, o.height, set_, kept_, o.layout, shTextures_)) {
        const size_t group = size_t(o.warpPixels) * size_t(o.warpsInFlight);
        chunk_ = (kChunkMin + group - 1) / group * group;
        orderVolumes();
        shadingPixels(tester);
        if (shTextures_ > 0) {
            shSampler_.emplace(set_, o.scenario, "cost model");
            shOptions_ = shSampleOptions(o.profile);
            variantNames_.push_back(shVariantName(o.profile));
        } else
            for (const GiVariant& v : allGiVariants()) {
                variantNames_.push_back(v.name());
                structures_.push_back(variantStructure(v));
            }
        replays_.reserve(variantNames_.size() * caches_.size()); // variant-major
        for (size_t v = 0; v < variantNames_.size(); ++v)
            for (const CacheConfig& cfg : caches_)
                replays_.emplace_back(cfg, table_);
        covered_.assign(order_.size(), 0);
        winner_.assign(order_.size(), -1);
        lookups_.resize(chunk_);
    }

    void drawVolumes() {
        for (int d : drawOrder_)
            c_.volumes.push_back(drawVolume(d));
    }

    void countTotals() {
        for (size_t i = 0; i < order_.size(); ++i) {
            c_.giPixels += covered_[i];
            if (winner_[i] >= 0)
                for (size_t k = 0; k < drawOrder_.size(); ++k)
                    if (drawOrder_[k] == winner_[i]) ++c_.volumes[k].won;
        }
        if (stencil_) {
            c_.drawCalls = c_.programBinds = c_.textureBinds = c_.textureUnbinds = -1;
            c_.depthCopyFetches = c_.targetPixels; // gi_depth_copy.frag: one depth read per texel
        } else if (shTextures_ > 0) {
            // GpuProbes::bindVolume: the coefficient textures and the mask per volume; the
            // pass then unbinds 2D, 2D-array and 3D on units 0 .. 5 + 8 - 1.
            c_.drawCalls = drawn_;
            c_.textureBinds = kGBufferTexturesBound + (shTextures_ + 1) * drawn_;
            c_.textureUnbinds = 3 * (kGBufferTexturesBound + kShUnitsBound);
        } else {
            c_.drawCalls = drawn_;
            c_.textureBinds = kGBufferTexturesBound + 3 * drawn_;
            c_.textureUnbinds = 2 * kUnitsUnbound;
        }
        c_.gbufferFetches = c_.depthCopyFetches;
        for (const VolumeCounters& v : c_.volumes) {
            c_.gbufferFetches += v.depthFetches + v.normalFetches + v.flagsFetches;
            c_.probeFetches += v.stateFetches + v.visibilityFetches + v.irradianceFetches +
                               v.shMaskFetches + v.shCoefficientFetches;
            c_.probeFootprintBytes += v.probeFootprintBytes;
            c_.probeTexels += v.probeTexels;
            c_.renderTargetBytesWritten += v.evaluated * std::uint64_t(c_.targetBytesPerPixel);
        }
        c_.fetchesPerGiPixel =
            c_.giPixels ? double(c_.gbufferFetches + c_.probeFetches) / double(c_.giPixels) : 0.0;
        c_.maxFetchesPerLookup =
            shTextures_ > 0
                ? kGBufferFetchesPerLookup + shTextures_ +
                      (o_.profile.gi.shLeak == profile::GiShLeak::None ? 0 : 1)
                : maxFetchesPerLookup(GiVariant{o_.profile.gi.probeOrder, o_.profile.gi.loops});
        c_.clearBytes = c_.targetPixels * std::uint64_t(c_.targetBytesPerPixel);
        for (int v : kept_)
            c_.gpuProbeBytes += shTextures_ > 0
                                    ? std::uint64_t(set_.volumes[size_t(v)].probeCount()) *
                                          probes::shGpuBytesPerProbe(shOptions_.coefficients)
                                    : profile::gpuVolumeBytes(set_, size_t(v));
    }

    std::vector<CacheResult> cacheResults() const {
        std::vector<CacheResult> results;
        for (size_t k = 0; k < replays_.size(); ++k) {
            CacheResult res;
            res.variant = variantNames_[k / caches_.size()];
            res.cache = caches_[k % caches_.size()];
            const CacheStats& s = replays_[k].stats();
            res.probeLines = s.probeLines;
            res.probeHits = s.probeHits;
            res.gbufferLines = s.gbufferLines;
            res.gbufferHits = s.gbufferHits;
            results.push_back(res);
        }
        return results;
    }

private:
    // Kept volumes in draw order: largest first, stencil smallest first.
    void orderVolumes() {
        std::vector<float> boxes;
        for (int v : kept_)
            boxes.push_back(set_.volumes[size_t(v)].boxVolume());
        drawOrder_ = profile::volumeDrawOrder(boxes, kept_);              // largest first
        if (stencil_) std::reverse(drawOrder_.begin(), drawOrder_.end()); // smallest first
    }

    // The target's pixels in shading order and the surface each one sees.
    void shadingPixels(const views::CoverageTester& tester) {
        describeTarget(o_, c_);
        order_ = gpuPixelOrder(c_.targetWidth, c_.targetHeight, o_.tile);
        // gi_ddgi_apply.frag reads GBuffer pixel fragCoord * divisor + (divisor - 1) / 2 (GL
        // rows count from the bottom; the rays' rows from the top).
        std::vector<glm::ivec2> rayPixels(order_.size());
        gbufferPx_.resize(order_.size());
        for (size_t i = 0; i < order_.size(); ++i) {
            gbufferPx_[i] = order_[i] * c_.divisor + (c_.divisor - 1) / 2;
            rayPixels[i] = {gbufferPx_[i].x, o_.height - 1 - gbufferPx_[i].y};
        }
        surface_ = tester.surfacePoints(view_, o_.width, o_.height, rayPixels);
    }

    VolumeCounters drawVolume(int d) {
        const int fileIndex = kept_[size_t(d)];
        VolumeCounters vc;
        vc.name = set_.volumes[size_t(fileIndex)].name;
        vc.fileIndex = fileIndex;
        vc.culled = std::find(o_.culledVolumes.begin(), o_.culledVolumes.end(), fileIndex) !=
                    o_.culledVolumes.end();
        if (vc.culled) return vc;
        ++drawn_;
        const TextureTable::Volume& tex = table_.volumes[size_t(d)];
        for (size_t start = 0; start < order_.size(); start += chunk_) {
            const size_t n = std::min(chunk_, order_.size() - start);
            lookUpChunk(fileIndex, start, n);
            countChunk(d, tex, start, n, vc);
            replayChunks(d, tex, start, n);
        }
        return vc;
    }

    // 1. The lookups of this chunk (parallel: one slot each).
    void lookUpChunk(int fileIndex, size_t start, size_t n) {
        pb::parallelFor(n, 0, [&](size_t i, int) {
            const views::SurfacePoint& s = surface_[start + i];
            Lookup& l = lookups_[i];
            const Lookup::Stage miss = stencil_ ? Lookup::Skipped : Lookup::Outside;
            l.stage = !s.hit                                            ? Lookup::Sky
                      : stencil_ && covered_[start + i]                 ? Lookup::Skipped
                      : sampler_.influencesPoint(fileIndex, s.position) ? Lookup::Evaluated
                                                                        : miss;
            if (stencil_ && l.stage == Lookup::Sky) l.stage = Lookup::Skipped;
            if (l.stage == Lookup::Evaluated && shSampler_)
                shSampler_->sampleVolume(fileIndex, s.position, s.normal,
                                         view_.position - s.position, shOptions_, &l.sh);
            else if (l.stage == Lookup::Evaluated)
                sampler_.sampleVolume(fileIndex, s.position, s.normal, view_.position - s.position,
                                      {}, &l.trace);
        });
    }

    // 2. Counters (the fetches are the same set in every variant: count the first).
    void countChunk(int d, const TextureTable::Volume& tex, size_t start, size_t n,
                    VolumeCounters& vc) {
        std::vector<Fetch> fetches;
        const VariantStructure* vs = structures_.empty() ? nullptr : &structures_[0];
        const glm::ivec3 counts = set_.volumes[size_t(kept_[size_t(d)])].counts;
        for (size_t i = 0; i < n; ++i) {
            fetches.clear();
            if (lookups_[i].stage == Lookup::Evaluated) {
                appendLookupFetches(lookups_[i], vs, tex, counts, fetches);
                covered_[start + i] = 1;
                winner_[start + i] = d;
            }
            countLookup(lookups_[i], fetches, table_, flagsRead_, vc);
        }
    }

    // 3. Every (variant, cache) replays the chunk in shading order (parallel: each replay
    //    owns its cache).
    void replayChunks(int d, const TextureTable::Volume& tex, size_t start, size_t n) {
        const glm::ivec3 counts = set_.volumes[size_t(kept_[size_t(d)])].counts;
        pb::parallelFor(replays_.size(), 0, [&](size_t k, int) {
            const size_t v = k / caches_.size();
            replayChunk(replays_[k], structures_.empty() ? nullptr : &structures_[v], table_, tex,
                        counts, lookups_.data(), gbufferPx_.data() + start, n, o_.warpPixels,
                        o_.warpsInFlight);
        });
    }

    const scene::View& view_;
    const CostModelOptions& o_;
    const probes::ProbeSet& set_;
    const std::vector<CacheConfig>& caches_;
    GiPassCounters& c_;
    const std::vector<int> kept_;
    const bool stencil_, flagsRead_;
    const int shTextures_; // gi.technique=sh_*: coefficient textures per volume; 0: DDGI
    const probes::ProbeSampler sampler_;
    std::optional<probes::ShSampler> shSampler_;
    probes::ShSampleOptions shOptions_;
    const TextureTable table_;
    std::vector<std::string> variantNames_; // DDGI: allGiVariants(); SH: one
    std::vector<VariantStructure> structures_;
    size_t chunk_ = 0;                  // pixels per step, whole SIMT groups
    std::vector<int> drawOrder_;        // indices into kept_
    std::vector<glm::ivec2> order_;     // target pixels in shading order
    std::vector<glm::ivec2> gbufferPx_; // the GBuffer pixel each one reads
    std::vector<views::SurfacePoint> surface_;
    std::vector<CacheReplay> replays_;  // variant-major: variants x caches
    std::vector<std::uint8_t> covered_; // stencil: 'any' set
    std::vector<int> winner_;
    std::vector<Lookup> lookups_;
    int drawn_ = 0;
};

} // namespace

CostReport runCostModel(const views::CoverageTester& tester, const scene::View& view,
                        const CostModelOptions& o) {
    if (o.width < 1 || o.height < 1) throw Error("cost model: resolution must be at least 1x1");
    if (o.warpPixels < 1 || o.warpPixels > 1024 || o.warpsInFlight < 1 || o.warpsInFlight > 256)
        throw Error("cost model: warp size must be in 1..1024 and warps in flight in 1..256");
    const probes::ProbeSet& set = tester.probes();
    if (o.scenario < 0 || o.scenario >= int(set.irradiance.size()))
        throw Error("cost model: the probe set has no scenario #" + std::to_string(o.scenario));
    const std::vector<CacheConfig> caches = o.caches.empty() ? cachePresets() : o.caches;
    for (const CacheConfig& c : caches)
        c.validate();

    CostReport r = describeRun(o, set);
    CostModelRun run(tester, view, o, caches, r.counters);
    run.drawVolumes();
    run.countTotals();
    r.results = run.cacheResults();
    return r;
}

} // namespace pb::costmodel
