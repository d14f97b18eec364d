// Stored / absent / invalid (probes/ProbeCounts.h): what the bake summary reports.
#include "probes/ProbeCounts.h"

#include "core/Error.h"

#include <array>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

// One volume per entry: `n` probes, the first `invalid` invalid (stored unless `sparse`), and
// with `sparse` the next `absent` valid ones not stored either.
ProbeSet probeCountsSetOf(const std::vector<std::array<int, 3>>& volumes, bool sparse) {
    ProbeSet s;
    for (const auto& [n, invalid, absent] : volumes) {
        std::vector<ProbeState> states(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            const bool inside = i < invalid, far = sparse && i >= invalid && i < invalid + absent;
            states[size_t(i)].stored = !(sparse && inside) && !far;
            states[size_t(i)].valid = !inside && !far; // in memory an absent probe is invalid
            states[size_t(i)].backfaceRatio = inside ? 1.0f : 0.0f; // as the geometry pass sets
        }
        s.states.push_back(states);
    }
    return s;
}

} // namespace

TEST(ProbeCounts, DenseSetsNeedNoBakeCounts) {
    const ProbeSet s = probeCountsSetOf({{10, 3, 0}, {4, 0, 0}}, false);
    const std::vector<std::size_t> bake{3, 0};
    for (const std::vector<std::size_t>* baked :
         {&bake, (const std::vector<std::size_t>*)nullptr}) {
        const std::vector<ProbeCounts> c = volumeProbeCounts(s, baked);
        ASSERT_EQ(c.size(), 2u);
        EXPECT_EQ(c[0].stored, 10u);
        EXPECT_EQ(c[0].absent, 0u);
        EXPECT_EQ(c[0].invalid, 3u); // dense files keep invalid probes, stored
        const ProbeCounts t = totalProbeCounts(c);
        EXPECT_EQ(t.probes, 14u);
        EXPECT_EQ(t.stored, 14u);
        EXPECT_EQ(t.absent, 0u);
        EXPECT_EQ(t.invalid, 3u);
    }
}

TEST(ProbeCounts, SparseSetsSplitWhatIsNotStoredWithTheBakesInvalidCount) {
    // Volume 0: 3 invalid + 5 absent of 12; volume 1 fully stored (no invalid probe).
    const ProbeSet s = probeCountsSetOf({{12, 3, 5}, {6, 0, 0}}, true);
    const std::vector<std::size_t> baked{3, 0};
    const std::vector<ProbeCounts> c = volumeProbeCounts(s, &baked);
    EXPECT_EQ(c[0].stored, 4u);
    EXPECT_EQ(c[0].absent, 5u);
    EXPECT_EQ(c[0].invalid, 3u);
    EXPECT_EQ(c[1].stored, 6u);
    EXPECT_EQ(c[1].absent, 0u);
    const ProbeCounts t = totalProbeCounts(c);
    EXPECT_EQ(t.stored + *t.absent + *t.invalid, t.probes);
    EXPECT_EQ(t.absent, 5u);

    // Read back from a file: the back-face ratios tell the 3 inside geometry from the 5 absent
    // ones lookups read stand-ins for, as the bake's count does.
    const std::vector<ProbeCounts> file = volumeProbeCounts(s, nullptr);
    EXPECT_EQ(file[0].absent, 5u);
    EXPECT_EQ(file[0].invalid, 3u);
    EXPECT_EQ(file[1].invalid, 0u);
    EXPECT_EQ(totalProbeCounts(file).absent, 5u);
    EXPECT_EQ(totalProbeCounts(file).stored, 10u);
}

TEST(ProbeCounts, CountsThatDoNotFitTheStatesAreAnError) {
    const ProbeSet s = probeCountsSetOf({{12, 3, 5}}, true);
    const std::vector<std::size_t> oneTooMany{9}, wrongSize{3, 0};
    EXPECT_THROW(volumeProbeCounts(s, &oneTooMany), pb::Error); // 9 > the 8 not stored
    EXPECT_THROW(volumeProbeCounts(s, &wrongSize), pb::Error);
}

// An absent probe may keep its irradiance (irradiance-only, valid): it counts as absent
// whatever its back-face ratio, and so do the stand-ins beside it (FreeSpace::Ranked keeps
// some tiles, not all).
TEST(ProbeCounts, IrradianceOnlyProbesTellAbsentFromInvalidWithoutBakeCounts) {
    ProbeSet s = probeCountsSetOf({{12, 3, 5}, {6, 0, 0}}, true);
    // Volume 0: probes 3..7 are the absent ones (setOf): irradiance-only and valid.
    for (std::size_t i = 0; i < s.states[0].size(); ++i) {
        ProbeState& p = s.states[0][i];
        p.valid = i >= 3;
        p.irradianceOnly = i >= 3 && i < 8;
    }
    const std::vector<ProbeCounts> file = volumeProbeCounts(s, nullptr);
    EXPECT_EQ(file[0].stored, 4u);
    EXPECT_EQ(file[0].absent, 5u);
    EXPECT_EQ(file[0].invalid, 3u);
    EXPECT_EQ(file[1].absent, 0u);
    const ProbeCounts t = totalProbeCounts(file);
    EXPECT_EQ(t.stored + *t.absent + *t.invalid, t.probes);
    // The bake's own count agrees with the states.
    const std::vector<std::size_t> baked{3, 0};
    EXPECT_EQ(volumeProbeCounts(s, &baked)[0].absent, 5u);
}

TEST(ProbeCounts, AMixOfTilesAndStandInsCountsEveryAbsentProbe) {
    ProbeSet s = probeCountsSetOf({{12, 3, 5}}, true);
    s.states[0][3].irradianceOnly = s.states[0][3].valid = true; // one of the 5 keeps a tile
    s.settings.backfaceThreshold = 0.25f;
    const std::vector<ProbeCounts> file = volumeProbeCounts(s, nullptr);
    EXPECT_EQ(file[0].absent, 5u);
    EXPECT_EQ(file[0].invalid, 3u);
    // A probe whose ratio is over the threshold is inside geometry, absent or not.
    s.states[0][4].backfaceRatio = 0.3f;
    EXPECT_EQ(volumeProbeCounts(s, nullptr)[0].invalid, 4u);
}
