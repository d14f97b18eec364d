// BC6H unsigned-float encoder: per block, the single-region modes (MS modes 11-14: 10-bit
// plain, 11/12/16-bit bases with 9/8/4-bit deltas) and, from Normal quality, the ten
// two-region modes on a shortlist of partitions ranked by a principal-axis estimate. The
// lowest error (see Bc6hFit.h for the space) wins. Deterministic: no randomness, no threads,
// only float arithmetic in a fixed order.
#include "probes/bc6h/Bc6h.h"
#include "probes/bc6h/Bc6hFit.h"

#include "core/Error.h"

#include <algorithm>
#include <limits>
#include <string>

namespace pb::probes {

using namespace bc6h;

namespace {

struct QualitySettings {
    int refineIterations;
    int precisionLevels;       // endpoint precisions tried per region count (0: all that fit)
    int partitionCandidates;   // two-region partitions tried in full (0: single-region only)
    int refinedTwoRegionModes; // best two-region modes per partition that get refined
    float skipTwoRegionBelow;  // block error under which two regions cannot pay off
    float pruneMargin;         // skip two regions when margin * best estimate >= error
    int perturbPasses;
};

QualitySettings settingsFor(Bc6hQuality q) {
    switch (q) {
    case Bc6hQuality::Fast:
        return {1, 2, 0, 0, 0.0f, 0.0f, 0};
    case Bc6hQuality::Normal:
        return {2, 2, 3, 2, 48.0f, 1.0f, 0};
    case Bc6hQuality::High:
        return {4, 0, 8, 4, 0.0f, 0.0f, 2};
    }
    return {2, 2, 3, 2, 48.0f, 1.0f, 0};
}

// Stable insertion sort of a few indices (std::sort on these tiny arrays trips GCC 12's
// -Warray-bounds false positives at -O2/-O3).
template <class Less> void sortIndices(int* a, int n, Less less) {
    for (int i = 1; i < n; ++i) {
        const int v = a[i];
        int j = i;
        for (; j > 0 && less(v, a[j - 1]); --j)
            a[j] = a[j - 1];
        a[j] = v;
    }
}

// Modes by decreasing endpoint precision. Among modes whose deltas reach the fitted endpoints
// the most precise one nearly always wins, and a mode that must clamp its deltas is not
// worth evaluating while a less precise one fits: the plain modes (MS 10 and 11) always fit.
constexpr int kSingleRegionOrder[] = {13, 12, 11, 10};
constexpr int kTwoRegionOrder[] = {2, 3, 4, 0, 5, 6, 7, 8, 1, 9};

// The modes of `order` whose deltas reach the nearest quantised endpoints, stopping after
// `levels` distinct precisions (0: no limit); returns how many candidates it wrote to `out`.
// Modes of one precision share the quantisation; the plain modes always fit.
template <std::size_t N>
int fittingModes(const int (&order)[N], const Lines& lines, int partition, int levels,
                 Encoding* out) {
    int count = 0, levelsSeen = 0, lastEpb = -1;
    int quantized[4][3] = {};
    for (int mode : order) {
        const ModeInfo& info = modeInfo(mode);
        if (info.epb != lastEpb) {
            if (levels > 0 && levelsSeen == levels) break;
            quantizeAbsolute(lines, info.epb, info.regions, quantized);
            lastEpb = info.epb;
        }
        Encoding enc;
        enc.mode = mode;
        enc.partition = partition;
        std::copy(&quantized[0][0], &quantized[0][0] + 12, &enc.ep[0][0]);
        if (!deltasRepresentable(enc)) continue;
        if (count == 0 || modeInfo(out[count - 1].mode).epb != info.epb) ++levelsSeen;
        out[count++] = enc;
    }
    return count;
}

Encoding encodeSingleRegion(const BlockTarget& t, const QualitySettings& s) {
    Lines lines;
    fitSubset(t, 0xFFFF, 0, 0, lines);
    Encoding candidates[4];
    const int n = fittingModes(kSingleRegionOrder, lines, 0, s.precisionLevels, candidates);
    Encoding best;
    for (int i = 0; i < n; ++i) {
        evaluate(t, candidates[i]);
        refine(t, candidates[i], s.refineIterations);
        if (candidates[i].error < best.error) best = candidates[i];
    }
    return best;
}

void tryTwoRegions(const BlockTarget& t, const QualitySettings& s, Encoding& best) {
    // Rank the 32 partitions by a cheap estimate, then encode the best few in full.
    // Partitions whose idealised estimate cannot beat what one region already achieves are
    // not worth encoding: the usual case for smooth probe data, and most of the time saved.
    const PartitionEstimator estimator(t);
    float score[32];
    estimator.scores(s.pruneMargin > 0.0f ? best.error / s.pruneMargin
                                          : std::numeric_limits<float>::infinity(),
                     score);
    int order[32];
    for (int p = 0; p < 32; ++p)
        order[p] = p;
    sortIndices(order, 32, [&](int a, int b) { return score[a] < score[b]; });
    if (score[order[0]] * s.pruneMargin >= best.error) return;

    for (int k = 0; k < s.partitionCandidates; ++k) {
        const int p = order[k];
        Lines lines;
        fitSubset(t, static_cast<std::uint16_t>(~kPartitions[p]), 0, 0, lines);
        fitSubset(t, kPartitions[p], kAnchor2[p], 1, lines);
        Encoding tried[kFirstSingleRegionMode];
        const int n = fittingModes(kTwoRegionOrder, lines, p, s.precisionLevels, tried);
        int rank[kFirstSingleRegionMode];
        for (int m = 0; m < n; ++m) {
            evaluate(t, tried[m]);
            rank[m] = m;
        }
        sortIndices(rank, n, [&](int a, int b) { return tried[a].error < tried[b].error; });
        for (int m = 0; m < std::min(n, s.refinedTwoRegionModes); ++m)
            refine(t, tried[rank[m]], s.refineIterations);
        for (int m = 0; m < n; ++m)
            if (tried[m].error < best.error) best = tried[m];
    }
}

void encodeBlock(const float* texels, const QualitySettings& s, std::uint8_t out[16]) {
    BlockTarget t;
    prepareTarget(texels, t);
    Encoding best = encodeSingleRegion(t, s);
    if (s.partitionCandidates > 0 && best.error > s.skipTwoRegionBelow) tryTwoRegions(t, s, best);
    if (s.perturbPasses > 0) perturb(t, best, s.perturbPasses);
    pack(best, out);
}

} // namespace

std::vector<std::uint8_t> encodeBc6hUf16(const float* rgb, int width, int height, int strideFloats,
                                         Bc6hQuality q) {
    if (width <= 0 || height <= 0 || width % 4 != 0 || height % 4 != 0)
        throw Error("BC6H encode: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not a positive multiple of 4");
    if (strideFloats < 2 || strideFloats > 4)
        throw Error("BC6H encode: stride " + std::to_string(strideFloats) +
                    " floats per texel is not 2, 3 or 4");
    if (rgb == nullptr) throw Error("BC6H encode: no input data");

    const QualitySettings settings = settingsFor(q);
    const int bw = width / 4, bh = height / 4;
    std::vector<std::uint8_t> blocks(static_cast<std::size_t>(bw) * bh * kBc6hBlockBytes);
    float texels[48];
    for (int by = 0; by < bh; ++by) {
        for (int bx = 0; bx < bw; ++bx) {
            for (int y = 0; y < 4; ++y) {
                for (int x = 0; x < 4; ++x) {
                    const std::size_t src =
                        ((static_cast<std::size_t>(by) * 4 + y) * width + bx * 4 + x) *
                        strideFloats;
                    float* dst = texels + (y * 4 + x) * 3;
                    dst[0] = rgb[src];
                    dst[1] = rgb[src + 1];
                    dst[2] = strideFloats == 2 ? 0.0f : rgb[src + 2];
                }
            }
            encodeBlock(texels, settings,
                        blocks.data() + (static_cast<std::size_t>(by) * bw + bx) * 16);
        }
    }
    return blocks;
}

} // namespace pb::probes
