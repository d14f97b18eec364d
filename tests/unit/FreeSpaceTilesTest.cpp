// Which left-out probes keep an irradiance tile (probes/store/FreeSpaceTiles.h, the default
// FreeSpace::Ranked): the ones whose stand-in is furthest off, as many as the budget holds.
#include "DenseAndSparseBake.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeLayout.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/SparseStorage.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::probes;

namespace {

// The rooms' 1500-probe test grid, baked dense: every probe traced, as the bake traces the
// left-out ones for Ranked.
const pb::test::DenseAndSparse& rooms() {
    static const pb::test::DenseAndSparse b =
        pb::test::bakeDenseAndSparse("rooms", 1500, FreeSpace::StandIns);
    return b;
}

std::vector<std::vector<std::uint8_t>> keepOf(const ProbeSet& set,
                                              const pb::scene::Scene& scene) {
    return {sparseKeptProbes(set.volumes[0], true, pb::raytrace::staticBakeTriangles(scene))};
}

// The set's memory with these tiles, as the budget counts it.
double bytesWith(const ProbeSet& traced, const std::vector<std::vector<std::uint8_t>>& keep,
                 const std::vector<std::vector<std::uint8_t>>& tiles) {
    ProbeSet s = traced;
    storeOnly(s, keep, tiles);
    return double(memoryReport(s).total.storedTotal());
}

} // namespace

TEST(FreeSpaceTiles, TheWorstStandInsGetTilesFirstAndTheBudgetHolds) {
    const ProbeSet& traced = rooms().dense;
    const auto keep = keepOf(traced, rooms().scene);
    const std::vector<std::vector<float>> err = standInErrors(traced, keep);
    const double base = bytesWith(traced, keep, {std::vector<std::uint8_t>(keep[0].size(), 0)});
    const double tile = double(bytesPerProbe(traced.format()).irradiance);
    // Budgets for about 10 and 60 tiles: both leave candidates out.
    for (double budget : {base + 10.5 * tile, base + 60.5 * tile}) {
        const FreeSpaceTileChoice c = chooseFreeSpaceTiles(traced, keep, budget);
        ASSERT_GT(c.chosen, 0u);
        ASSERT_LT(c.chosen, c.candidates) << "every candidate fits: the order is not tested";
        EXPECT_LE(bytesWith(traced, keep, c.tiles), budget);
        float lowestChosen = std::numeric_limits<float>::infinity(), highestLeft = 0.0f;
        std::size_t n = 0;
        for (std::size_t p = 0; p < keep[0].size(); ++p) {
            if (c.tiles[0][p]) {
                EXPECT_FALSE(keep[0][p]) << "a stored probe got a tile: " << p;
                EXPECT_TRUE(traced.states[0][p].valid) << "an invalid probe got a tile: " << p;
                lowestChosen = std::min(lowestChosen, err[0][p]);
                ++n;
            } else if (!keep[0][p] && traced.states[0][p].valid) {
                highestLeft = std::max(highestLeft, err[0][p]);
            }
        }
        EXPECT_EQ(n, c.chosen);
        EXPECT_GE(lowestChosen, highestLeft) << "a better candidate was left out";
        EXPECT_EQ(c.worstLeft, highestLeft);
        EXPECT_GT(highestLeft, 0.0f);
        // As many as fit: one more tile (the next in rank) would not.
        std::vector<std::vector<std::uint8_t>> more = c.tiles;
        for (std::size_t p = 0; p < keep[0].size(); ++p)
            if (!more[0][p] && !keep[0][p] && traced.states[0][p].valid &&
                err[0][p] == highestLeft) {
                more[0][p] = 1;
                break;
            }
        EXPECT_GT(bytesWith(traced, keep, more), budget);
    }
}

TEST(FreeSpaceTiles, NoBudgetLeftMeansNoTilesAndAmpleBudgetMeansAll) {
    const ProbeSet& traced = rooms().dense;
    const auto keep = keepOf(traced, rooms().scene);
    const double base = bytesWith(traced, keep, {std::vector<std::uint8_t>(keep[0].size(), 0)});
    // Already over the budget: no tile.
    const FreeSpaceTileChoice none = chooseFreeSpaceTiles(traced, keep, base - 1.0);
    EXPECT_EQ(none.chosen, 0u);
    EXPECT_GT(none.candidates, 0u);
    EXPECT_GT(none.worstLeft, 0.0f);
    // Exactly at it: only the free slots of the packed texture's last layer, at no cost.
    const FreeSpaceTileChoice free = chooseFreeSpaceTiles(traced, keep, base);
    EXPECT_EQ(bytesWith(traced, keep, free.tiles), base);
    EXPECT_LT(free.chosen, free.candidates);
    const FreeSpaceTileChoice all = chooseFreeSpaceTiles(traced, keep, 100.0 * base);
    EXPECT_EQ(all.chosen, all.candidates);
    EXPECT_EQ(all.worstLeft, 0.0f);
    // All of them is what FreeSpace::Irradiance keeps.
    ProbeSet ranked = traced, irradiance = traced;
    storeOnly(ranked, keep, all.tiles);
    storeOnly(irradiance, keep, FreeSpace::Irradiance);
    for (std::size_t p = 0; p < keep[0].size(); ++p)
        EXPECT_EQ(ranked.states[0][p].irradianceOnly, irradiance.states[0][p].irradianceOnly) << p;
}

TEST(FreeSpaceTiles, WithoutABudgetTheTilesGetTheirShareOfTheWhole) {
    const ProbeSet& traced = rooms().dense;
    const auto keep = keepOf(traced, rooms().scene);
    const double base = bytesWith(traced, keep, {std::vector<std::uint8_t>(keep[0].size(), 0)});
    const FreeSpaceTileChoice c = chooseFreeSpaceTiles(traced, keep, 0.0);
    EXPECT_EQ(defaultFreeSpaceBudget(base), base / (1.0 - kFreeSpaceTileShare));
    const double with = bytesWith(traced, keep, c.tiles);
    EXPECT_LE(with, defaultFreeSpaceBudget(base));
    ASSERT_GT(c.chosen, 0u);
    ASSERT_LT(c.chosen, c.candidates);
    // As many as fit: the next in rank would not (the packed texture grows by whole layers).
    const std::vector<std::vector<float>> err = standInErrors(traced, keep);
    std::vector<std::vector<std::uint8_t>> more = c.tiles;
    for (std::size_t p = 0; p < keep[0].size(); ++p)
        if (!more[0][p] && !keep[0][p] && traced.states[0][p].valid && err[0][p] == c.worstLeft) {
            more[0][p] = 1;
            break;
        }
    EXPECT_GT(bytesWith(traced, keep, more), defaultFreeSpaceBudget(base));
}

// A left-out probe read as its stand-in scores 0 only when its light equals the stand-in's;
// one whose stand-in is far off scores high. Here: the scores are what the tiles say.
TEST(FreeSpaceTiles, AProbeWithItsStandInsLightScoresZero) {
    ProbeSet traced = rooms().dense;
    const auto keep = keepOf(traced, rooms().scene);
    std::vector<std::vector<float>> err = standInErrors(traced, keep);
    std::size_t worst = 0;
    for (std::size_t p = 0; p < err[0].size(); ++p)
        if (err[0][p] > err[0][worst]) worst = p;
    ASSERT_GT(err[0][worst], 0.15f) << "no stand-in is off: the scene tests nothing";
    ASSERT_TRUE(std::isfinite(err[0][worst]));
    // Copy the stand-in's tile over the worst probe's: its score drops to 0, no other changes.
    std::vector<ProbeState> stored = traced.states[0];
    for (std::size_t p = 0; p < stored.size(); ++p) {
        stored[p].stored = stored[p].valid && keep[0][p];
        stored[p].valid = stored[p].stored;
    }
    const int from =
        fillSources(traced.volumes[0], stored, traced.settings.backfaceThreshold)[worst];
    ASSERT_GE(from, 0);
    ProbeTexture& t = traced.irradiance[0][0];
    const glm::ivec3 a = traced.volumes[0].probeCoords(int(worst)),
                     b = traced.volumes[0].probeCoords(from);
    for (int y = 0; y < kIrradianceTile; ++y)
        for (int x = 0; x < kIrradianceTile; ++x)
            for (int ch = 0; ch < t.shape.channels; ++ch)
                t.at(a.x * kIrradianceTile + x, a.z * kIrradianceTile + y, a.y)[ch] =
                    t.at(b.x * kIrradianceTile + x, b.z * kIrradianceTile + y, b.y)[ch];
    const std::vector<std::vector<float>> after = standInErrors(traced, keep);
    EXPECT_EQ(after[0][worst], 0.0f);
    for (std::size_t p = 0; p < err[0].size(); ++p)
        if (p != worst && !keep[0][p]) {
            EXPECT_EQ(after[0][p], err[0][p]) << p;
        }
}
