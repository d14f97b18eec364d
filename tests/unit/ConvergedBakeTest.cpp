// The converged bake (Baker.h, BakeSettings::bounces = 0): bounce passes until the last adds
// under kConvergedChange of the light, each later pass an increment traced with fewer rays, and
// a noise figure for the final irradiance that a second seed confirms.
#include "core/Luminance.h"
#include "probes/ProbeLayout.h"
#include "probes/bake/Baker.h"
#include "probes/bake/NoiseRounds.h"
#include "probes/sh/ShIrradiance.h"
#include "scene/BuiltinScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace pb;
using namespace pb::probes;

namespace {

// The Cornell box's inside: white walls bounce much of the light, so it needs many passes.
BakeRequest cornellBake(int bounces, std::uint64_t seed = 1) {
    const scene::Scene s = scene::makeCornellScene();
    BakeRequest req;
    req.volumes = {ProbeVolume{}};
    req.volumes[0].name = "inside";
    req.volumes[0].center = {0.0f, 1.0f, 0.0f};
    req.volumes[0].halfExtents = glm::vec3(0.9f);
    req.volumes[0].counts = {5, 5, 5};
    req.scenarios = {Scenario{"day", s.sun, s.sky}};
    req.settings.raysPerProbe = 64;
    req.settings.bounces = bounces;
    req.settings.seed = seed;
    req.settings.format = StorageFormat::Rgba32f; // no quantisation in the comparisons
    return req;
}

// Per valid probe: the interior texels' luminance (row-major, kIrradianceInteriorTexels each).
std::vector<std::vector<float>> probeLuminances(const ProbeSet& set) {
    std::vector<std::vector<float>> out;
    const ProbeVolume& vol = set.volumes[0];
    const ProbeTexture& tex = set.irradiance[0][0];
    for (int p = 0; p < vol.probeCount(); ++p) {
        if (!set.states[0][std::size_t(p)].valid) continue;
        const float* tile = tileOrigin(tex, vol.probeCoords(p), kIrradianceTile);
        std::vector<float> y;
        for (int ty = 1; ty <= kIrradianceInterior; ++ty)
            for (int tx = 1; tx <= kIrradianceInterior; ++tx) {
                const float* t = tile + (std::size_t(ty) * std::size_t(tex.shape.width) +
                                         std::size_t(tx)) * 4;
                y.push_back(luminance(glm::vec3(t[0], t[1], t[2])));
            }
        out.push_back(y);
    }
    return out;
}

double meanOf(const std::vector<std::vector<float>>& ys) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& y : ys)
        for (float v : y) {
            sum += v;
            ++n;
        }
    return n > 0 ? sum / double(n) : 0.0;
}

} // namespace

TEST(ConvergedBake, LaterPassesTraceFewerRays) {
    EXPECT_EQ(passRays(256, 1), 256);
    EXPECT_EQ(passRays(256, 2), 256);
    EXPECT_EQ(passRays(256, 3), 128);
    EXPECT_EQ(passRays(256, 5), 32);
    EXPECT_EQ(passRays(256, 24), kMinIncrementRays);
    EXPECT_EQ(passRays(16, 9), 16) << "never more than asked";
}

TEST(ConvergedBake, PassesGoOnUntilTheLastAddsUnderOnePercent) {
    const scene::Scene s = scene::makeCornellScene();
    BakeStats conv, two, most;
    const ProbeSet converged = bakeProbes(s, cornellBake(0), &conv);
    ASSERT_EQ(conv.passes.size(), 1u);
    const int passes = conv.passes[0];
    std::printf("[ converged ] cornell: %d passes, the last added %.3f%% of the light\n", passes,
                100.0 * conv.lastChange[0]);
    EXPECT_GT(passes, 2) << "white walls: more than two bounces matter";
    EXPECT_LT(passes, kMaxBouncePasses);
    EXPECT_LT(conv.lastChange[0], kConvergedChange);

    // The same pass count asked for: the same bytes (a converged bake is a fixed count that
    // the change chose); one fewer pass added more than the threshold.
    BakeStats fixedStats;
    EXPECT_EQ(bakeProbes(s, cornellBake(passes), &fixedStats).irradiance[0][0].texels,
              converged.irradiance[0][0].texels);
    BakeStats fewer;
    bakeProbes(s, cornellBake(passes - 1), &fewer);
    EXPECT_GE(fewer.lastChange[0], kConvergedChange);

    // All the light: more than two bounces give, and within 2% of what the cap's passes give.
    const double meanConverged = meanOf(probeLuminances(converged));
    const double meanTwo = meanOf(probeLuminances(bakeProbes(s, cornellBake(2), &two)));
    const double meanMost =
        meanOf(probeLuminances(bakeProbes(s, cornellBake(kMaxBouncePasses), &most)));
    std::printf("[ converged ] mean luminance: 2 passes %.4f, converged %.4f, %d passes %.4f\n",
                meanTwo, meanConverged, kMaxBouncePasses, meanMost);
    EXPECT_GT(meanConverged, 1.15 * meanTwo);
    EXPECT_NEAR(meanConverged, meanMost, 0.02 * meanMost);
}

// The reported noise (relative standard error of each probe's final irradiance, NoiseRounds.h)
// against what a second seed shows: per probe, RMS over its texels of (Y1 - Y2) / sqrt(2), over
// its mean luminance (floored as the bake floors it). The means agree within 1.5x.
TEST(ConvergedBake, NoiseAgreesWithATwoSeedDifference) {
    const scene::Scene s = scene::makeCornellScene();
    BakeStats a, b;
    const auto y1 = probeLuminances(bakeProbes(s, cornellBake(0, 1), &a));
    const auto y2 = probeLuminances(bakeProbes(s, cornellBake(0, 2), &b));
    ASSERT_EQ(y1.size(), y2.size());
    ASSERT_FALSE(y1.empty());
    const double floor = double(kNoiseFloorShare) * meanOf(y1);
    double measured = 0.0;
    for (std::size_t p = 0; p < y1.size(); ++p) {
        double d2 = 0.0, m = 0.0;
        for (std::size_t t = 0; t < y1[p].size(); ++t) {
            const double d = double(y1[p][t]) - double(y2[p][t]);
            d2 += d * d / double(y1[p].size());
            m += 0.5 * (double(y1[p][t]) + double(y2[p][t])) / double(y1[p].size());
        }
        measured += std::sqrt(d2 / 2.0) / std::max(m, floor) / double(y1.size());
    }
    const double reported = 0.5 * (a.noiseMean + b.noiseMean);
    std::printf("[ converged ] noise: reported mean %.4f (seeds 1, 2: %.4f, %.4f), two-seed "
                "difference %.4f; %d and %d passes\n",
                reported, a.noiseMean, b.noiseMean, measured, a.passes[0], b.passes[0]);
    EXPECT_LT(reported, 1.5 * measured);
    EXPECT_GT(reported, measured / 1.5);
}

// The SH technique's record (the passes' ray samples projected, summed like the tiles) holds
// the same light as the irradiance tiles: its DC term against the tile's map projection, for
// one pass and for the converged bake.
TEST(ConvergedBake, TheShRecordHoldsEveryPassLikeTheTiles) {
    const scene::Scene s = scene::makeCornellScene();
    for (int bounces : {1, 0}) {
        const ProbeSet set = bakeProbes(s, cornellBake(bounces));
        const ProbeVolume& vol = set.volumes[0];
        double worst = 0.0, sumRecord = 0.0, sumMap = 0.0;
        for (int p = 0; p < vol.probeCount(); ++p) {
            if (!set.states[0][std::size_t(p)].valid) continue;
            const ShCoefficients map = projectIrradianceTile(vol.probeCoords(p), set.irradiance[0][0]);
            const float record = luminance(set.sh[0][0][std::size_t(p) * kShL2Coefficients]);
            const float dc = luminance(map[0]);
            sumRecord += record;
            sumMap += dc;

            worst = std::max(worst, double(std::fabs(record - dc) / std::max(dc, 1e-3f)));
        }
        std::printf("[ converged ] bounces %d: SH record DC sum %.4f, tile projection %.4f, "
                    "worst probe %.3f\n",
                    bounces, sumRecord, sumMap, worst);
        EXPECT_NEAR(sumRecord, sumMap, 0.02 * sumMap) << "bounces " << bounces;
    }
}
