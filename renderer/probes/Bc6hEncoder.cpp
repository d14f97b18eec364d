// BC6H unsigned-float encoder: per block, the single-region modes (MS modes 11-14: 10-bit
// plain, 11/12/16-bit bases with 9/8/4-bit deltas) and, from Normal quality, the ten
// two-region modes on a shortlist of partitions ranked by a principal-axis estimate. The
// lowest error (see Bc6hFit.h for the space) wins. Deterministic: no randomness, no threads,
// only float arithmetic in a fixed order.
#include "probes/Bc6h.h"
#include "probes/Bc6hFit.h"

#include "core/Error.h"

#include <algorithm>
#include <string>

namespace pb::probes {

using namespace bc6h;

namespace {

struct QualitySettings {
    int refineIterations;
    int partitionCandidates; // two-region partitions tried in full (0: single-region only)
    int refinedTwoRegionModes; // best two-region modes per partition that get refined
    float skipTwoRegionBelow;  // block error under which two regions cannot pay off
    float pruneMargin;         // skip two regions when margin * best estimate >= error
    int perturbPasses;
};

QualitySettings settingsFor(Bc6hQuality q) {
    switch (q) {
    case Bc6hQuality::Fast: return {1, 0, 0, 0.0f, 0.0f, 0};
    case Bc6hQuality::Normal: return {2, 3, 2, 48.0f, 1.0f, 0};
    case Bc6hQuality::High: return {4, 8, 4, 0.0f, 0.0f, 2};
    }
    return {2, 3, 2, 48.0f, 1.0f, 0};
}

Encoding encodeSingleRegion(const BlockTarget& t, const QualitySettings& s) {
    Lines lines;
    fitSubset(t, 0xFFFF, 0, 0, lines);
    Encoding best;
    for (int mode = kFirstSingleRegionMode; mode < kModeCount; ++mode) {
        Encoding enc;
        enc.mode = mode;
        quantizeEndpoints(lines, enc);
        evaluate(t, enc);
        refine(t, enc, s.refineIterations);
        if (enc.error < best.error) best = enc;
    }
    return best;
}

void tryTwoRegions(const BlockTarget& t, const QualitySettings& s, Encoding& best) {
    // Rank the 32 partitions by a cheap estimate, then encode the best few in full.
    const PartitionEstimator estimator(t);
    int order[32];
    float score[32];
    for (int p = 0; p < 32; ++p) {
        order[p] = p;
        score[p] = estimator.score(p);
    }
    std::stable_sort(order, order + 32, [&](int a, int b) { return score[a] < score[b]; });
    // Even the idealised estimate of the best split cannot beat what one region already
    // achieves: the usual case for smooth probe data, and most of the encoding time saved.
    if (score[order[0]] * s.pruneMargin >= best.error) return;

    for (int k = 0; k < s.partitionCandidates; ++k) {
        const int p = order[k];
        Lines lines;
        fitSubset(t, static_cast<std::uint16_t>(~kPartitions[p]), 0, 0, lines);
        fitSubset(t, kPartitions[p], kAnchor2[p], 1, lines);
        Encoding tried[kFirstSingleRegionMode];
        for (int mode = 0; mode < kFirstSingleRegionMode; ++mode) {
            tried[mode].mode = mode;
            tried[mode].partition = p;
            quantizeEndpoints(lines, tried[mode]);
            evaluate(t, tried[mode]);
        }
        std::stable_sort(tried, tried + kFirstSingleRegionMode,
                         [](const Encoding& a, const Encoding& b) { return a.error < b.error; });
        for (int m = 0; m < s.refinedTwoRegionModes; ++m) refine(t, tried[m], s.refineIterations);
        for (int m = 0; m < kFirstSingleRegionMode; ++m)
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

std::vector<std::uint8_t> encodeBc6hUf16(const float* rgb, int width, int height,
                                         int strideFloats, Bc6hQuality q) {
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
