// Split bakes: the parts of a scenario split, merged, are the whole bake's probe file byte for
// byte (sparse and dense, any part order), and the merge refuses parts that do not belong
// together.
#include "probes/store/ProbeFileParts.h"
#include "ProbeTestScenes.h"
#include "SunlitFloorBake.h"
#include "core/Error.h"
#include "probes/bake/Baker.h"
#include "raytrace/StaticTriangles.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/MemoryReport.h"
#include "scene/SceneLoader.h"
#include "probes/store/ProbeFile.h"

#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

BakeRequest probeFilePartsRequest(const pb::scene::Scene& s, bool sparse) {
    BakeRequest r = pb::test::sunlitFloorRequest(s);
    r.scenarios.push_back({"dusk", r.scenarios[0].sun, {glm::vec3(0.2f, 0.1f, 0.05f)}});
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 2;
    r.sparse = sparse;
    return r;
}

ProbeFilePart bakePart(const pb::scene::Scene& s, BakeRequest r, int part, int parts) {
    r.onlyScenarios = scenarioSplit(r.scenarios.size(), part, parts);
    ProbeFilePart p;
    p.part = std::uint32_t(part);
    p.parts = std::uint32_t(parts);
    p.totalScenarios = std::uint32_t(r.scenarios.size());
    for (std::size_t i : r.onlyScenarios)
        p.scenarios.push_back(std::uint32_t(i));
    p.set = bakeProbes(s, r);
    // Through the file format, as bake-merge sees it.
    return parseProbeFilePart(serializeProbeFilePart(p), "part" + std::to_string(part));
}

std::string mergeError(const std::vector<ProbeFilePart>& parts) {
    try {
        mergeProbeFileParts(parts, {"a.pbpart", "b.pbpart", "c.pbpart"});
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST(ProbeFileParts, ScenarioSplitGivesContiguousBlocks) {
    EXPECT_EQ(scenarioSplit(3, 0, 2), (std::vector<std::size_t>{0, 1}));
    EXPECT_EQ(scenarioSplit(3, 1, 2), (std::vector<std::size_t>{2}));
    EXPECT_EQ(scenarioSplit(2, 1, 2), (std::vector<std::size_t>{1}));
    EXPECT_THROW(scenarioSplit(2, 0, 3), pb::Error); // a part with nothing to bake
    EXPECT_THROW(scenarioSplit(2, 2, 2), pb::Error);
    EXPECT_THROW(scenarioSplit(2, -1, 2), pb::Error);
}

TEST(ProbeFileParts, MergedPartsAreTheSingleBakeByteForByte) {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    for (bool sparse : {false, true}) {
        const BakeRequest r = probeFilePartsRequest(s, sparse);
        const std::vector<std::uint8_t> single = serializeProbeSet(bakeProbes(s, r));
        // Out of order on purpose: the merge orders scenarios by their index in the bake.
        const std::vector<ProbeFilePart> parts = {bakePart(s, r, 1, 2), bakePart(s, r, 0, 2)};
        EXPECT_EQ(parts[0].set.scenarios.size(), 1u);
        EXPECT_EQ(parts[1].set.scenarios.size(), 2u);
        const ProbeSet merged = mergeProbeFileParts(parts, {"b", "a"});
        EXPECT_TRUE(serializeProbeSet(merged) == single) << "sparse " << sparse;
    }
}

// Ranked free-space tiles rank every scenario's light: the parts keep every left-out probe's
// tile, the merge chooses as the whole bake does - byte for byte.
TEST(ProbeFileParts, MergedPartsMakeTheWholeBakesRankedTileChoice) {
    const pb::scene::Scene s = pb::scene::makeBuiltinScene("courtyard"); // air to leave out
    BakeRequest r;
    r.volumes.push_back(fitAutoVolume(pb::raytrace::staticBakeBounds(s), 0.0f, 1500).volume);
    r.scenarios = resolveScenarios({"day", "night"}, {}, s);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 1;
    r.sparse = true;
    // A budget that holds some of the left-out probes' tiles, not all.
    const ProbeSet standIns = bakeProbes(s, r);
    ProbeSet all = standIns;
    r.freeSpace = FreeSpace::Irradiance;
    all = bakeProbes(s, r);
    r.freeSpace = FreeSpace::Ranked;
    r.freeSpaceBudgetBytes = 0.5 * double(memoryReport(standIns).total.storedTotal() +
                                          memoryReport(all).total.storedTotal());
    const ProbeSet whole = bakeProbes(s, r);
    const std::vector<ProbeFilePart> parts = {bakePart(s, r, 0, 2), bakePart(s, r, 1, 2)};
    std::size_t tiles = 0, partTiles = 0, absent = 0;
    for (std::size_t v = 0; v < whole.states.size(); ++v)
        for (std::size_t i = 0; i < whole.states[v].size(); ++i) {
            tiles += whole.states[v][i].irradianceOnly ? 1 : 0;
            partTiles += parts[0].set.states[v][i].irradianceOnly ? 1 : 0;
            absent += !whole.states[v][i].stored ? 1 : 0;
        }
    ASSERT_GT(tiles, 0u) << "no tile chosen: vacuous";
    ASSERT_GT(partTiles, tiles) << "the parts already chose: nothing left to the merge";
    EXPECT_EQ(parts[0].set.freeSpace, FreeSpace::Ranked);
    const ProbeSet merged = mergeProbeFileParts(parts, {"a", "b"});
    EXPECT_TRUE(serializeProbeSet(merged) == serializeProbeSet(whole));
}

TEST(ProbeFileParts, APartsScenarioIsSeededByItsIndexInTheWholeBake) {
    // Baking "night" alone as the first scenario is another bake (another seed stream) than
    // baking it as the whole bake's second: the split must not do that.
    const pb::scene::Scene s = pb::test::sunlitFloor();
    BakeRequest r = probeFilePartsRequest(s, false);
    const ProbeFilePart second = bakePart(s, r, 1, 3); // "night", index 1
    BakeRequest alone = r;
    alone.scenarios = {r.scenarios[2], r.scenarios[1]}; // night at index 1 again
    alone.onlyScenarios = {1};
    const ProbeSet same = bakeProbes(s, alone);
    EXPECT_EQ(same.irradiance[0][0].stored, second.set.irradiance[0][0].stored);
    alone.scenarios = {r.scenarios[1]}; // night at index 0: another stream
    alone.onlyScenarios = {};
    const ProbeSet other = bakeProbes(s, alone);
    EXPECT_NE(other.irradiance[0][0].stored, second.set.irradiance[0][0].stored);
}

TEST(ProbeFileParts, MergeRefusesPartsThatDoNotBelongTogether) {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    const BakeRequest r = probeFilePartsRequest(s, false);
    const ProbeFilePart p0 = bakePart(s, r, 0, 2), p1 = bakePart(s, r, 1, 2);
    EXPECT_NE(mergeError({p0}).find("part 1 of 2 is missing"), std::string::npos)
        << mergeError({p0});
    EXPECT_NE(mergeError({p0, p0}).find("b.pbpart: part 0 given twice (also a.pbpart)"),
              std::string::npos)
        << mergeError({p0, p0});
    BakeRequest seeded = r;
    seeded.settings.seed = 7;
    const ProbeFilePart foreign = bakePart(s, seeded, 1, 2);
    EXPECT_NE(mergeError({p0, foreign}).find("b.pbpart: is a part of another bake"),
              std::string::npos)
        << mergeError({p0, foreign});
    // Same hash and split, different geometry bytes (a build that bakes differently).
    ProbeFilePart odd = p1;
    odd.set.states[0][0].backfaceRatio += 0.5f;
    EXPECT_NE(mergeError({p0, odd}).find("probe states or visibility differ"), std::string::npos)
        << mergeError({p0, odd});
}

TEST(ProbeFileParts, DamagedPartFilesGiveOneLineErrors) {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    const ProbeFilePart p = bakePart(s, probeFilePartsRequest(s, false), 0, 2);
    std::vector<std::uint8_t> bytes = serializeProbeFilePart(p);
    bytes[bytes.size() / 2] ^= 0x40;
    try {
        parseProbeFilePart(bytes, "x.pbpart");
        FAIL() << "a flipped bit was read";
    } catch (const pb::Error& e) {
        EXPECT_EQ(std::string(e.what()), "x.pbpart: checksum mismatch (the part file is corrupt)");
    }
    std::vector<std::uint8_t> probeFile = serializeProbeSet(p.set);
    EXPECT_THROW(parseProbeFilePart(probeFile, "y.pbp"), pb::Error); // a probe file, not a part
}
