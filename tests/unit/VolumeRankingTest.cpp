// Volume ranking (costmodel/VolumeRanking.h), its sidecar file (probes/store/VolumeRanksFile.h) and
// gi.volume_lod=rank_budget_mib (profile/GiVolumeLod.h), GL-free. The probe set is synthetic
// over the built-in `rooms`: a root over the house lit uniformly, a child over the sunlit room
// lit five times brighter (it obviously matters in the sunlit room's view), and a child over
// the dark room that view never sees, listed first so that file order would pick it.
#include "gl/GiSyntheticProbes.h"

#include "core/Error.h"
#include "profile/GiVolumeLod.h"
#include "costmodel/VolumeRanking.h"
#include "probes/store/VolumeRanksFile.h"
#include "profile/VolumeLod.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pb::test {
namespace {

const scene::Scene& volumeRankingRooms() {
    static const scene::Scene s = scene::makeBuiltinScene("rooms");
    return s;
}

probes::ProbeSet roomsProbes() {
    probes::ProbeSet set = syntheticProbes(
        {syntheticVolume("house", {0.0f, 1.3f, 0.0f}, {4.3f, 1.6f, 2.8f}, {9, 4, 6}),
         // x in [0.05, 4.1]: clear of the middle wall, whose sunlit face the seen child holds.
         syntheticVolume("unseen", {2.075f, 1.3f, 0.0f}, {2.025f, 1.35f, 2.55f}, {5, 4, 6},
                         "house"),
         syntheticVolume("seen", {-2.025f, 1.3f, 0.0f}, {2.05f, 1.35f, 2.55f}, {5, 4, 6}, "house")},
        [](int v, const glm::vec3&, const glm::ivec3&) {
            return v == 2 ? glm::vec3(5.0f) : glm::vec3(1.0f);
        },
        probes::StorageFormat::Rgba16f);
    set.inputHash = 0x1234;
    return set;
}

// Inside the sunlit room looking at its west wall: the dark room is off-screen.
scene::View westWall() {
    return {"west_wall", {-1.0f, 1.4f, 0.0f}, {-4.0f, 1.2f, 0.0f}, 60.0f};
}

probes::VolumeRanks rank(const probes::ProbeSet& set, const std::vector<scene::View>& views) {
    costmodel::RankingInputs in;
    in.scene = &volumeRankingRooms();
    in.probes = &set;
    in.views = views;
    in.viewsLabel = "test";
    in.width = 64;
    in.height = 36;
    in.ambientUp = glm::vec3(0.5f);
    in.ambientDown = glm::vec3(0.2f);
    return costmodel::rankVolumes(in);
}

double mibOf(std::uint64_t bytes) {
    return double(bytes) / (1024.0 * 1024.0);
}

TEST(VolumeRanking, TheVolumeThatCoversTheViewOutranksTheOneOffScreen) {
    const probes::ProbeSet set = roomsProbes();
    const probes::VolumeRanks r = rank(set, {westWall()});
    ASSERT_EQ(r.volumes.size(), 3u);
    const probes::VolumeRank &house = r.volumes[0], &unseen = r.volumes[1], &seen = r.volumes[2];
    EXPECT_EQ(unseen.pixels, 0);
    EXPECT_EQ(unseen.views, 0);
    EXPECT_EQ(unseen.loss, 0.0) << "no pixel of the view changes";
    EXPECT_GT(seen.pixels, 64 * 36 / 2);
    EXPECT_GT(seen.loss, 0.1) << "5x brighter than its parent over most of the view";
    // Omitting the root omits both children: its loss includes the seen child's region.
    EXPECT_GT(house.loss, seen.loss);
    EXPECT_EQ(house.bytes,
              house.bytes > 0
                  ? unseen.bytes + seen.bytes + profile::gpuVolumeBytes(set.volumes[0], set.format())
                  : 0);
    EXPECT_EQ(house.lookupsSaved, house.pixels) << "nothing else covers the house";
    EXPECT_EQ(seen.lookupsSaved, 0) << "the parent takes the child's pixels over";
    EXPECT_GE(seen.lookups, seen.pixels);
    EXPECT_EQ(costmodel::byLoss(r), (std::vector<int>{0, 2, 1}));
    // Deterministic: the same numbers again.
    EXPECT_EQ(probes::volumeRanksJson(rank(set, {westWall()})), probes::volumeRanksJson(r));
}

TEST(VolumeRanking, UniformLightingMakesAVisibleChildWorthNothing) {
    probes::ProbeSet set = roomsProbes();
    // The dark room's view sees the "unseen" child, but it is lit exactly like its parent.
    const probes::VolumeRanks r = rank(set, {*volumeRankingRooms().findView("dark_room")});
    EXPECT_GT(r.volumes[1].pixels, 0);
    EXPECT_LT(r.volumes[1].loss, 1e-6);
}

TEST(VolumeRanking, RankBudgetDropsTheLowValueVolumeFirst) {
    probes::ProbeSet set = roomsProbes();
    const auto bytes = [&](int v) {
        return profile::gpuVolumeBytes(set.volumes[size_t(v)], set.format());
    };
    const double withoutOneChild = mibOf(bytes(0) + bytes(1));
    auto kept = [&](double mib) {
        return profile::selectVolumes(set, {profile::VolumeLod::Mode::RankBudgetMiB, {}, mib});
    };
    EXPECT_THROW(kept(100.0), Error) << "no ranks: an error even when everything fits";
    try {
        kept(100.0);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("probebench volumes --rank --write-ranks"),
                  std::string::npos)
            << e.what();
    }
    // budget_mib (coarsest first, then file order) keeps the child the view never sees...
    EXPECT_EQ(
        profile::selectVolumes(set, {profile::VolumeLod::Mode::BudgetMiB, {}, withoutOneChild}),
        (std::vector<int>{0, 1}));
    // ...rank_budget_mib keeps the one that matters.
    set.ranks = rank(set, {westWall()});
    EXPECT_EQ(kept(100.0), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(kept(withoutOneChild), (std::vector<int>{0, 2}));
    EXPECT_EQ(kept(mibOf(bytes(0)) * 1.01), (std::vector<int>{0}));
    EXPECT_THROW(kept(mibOf(bytes(0)) * 0.5), Error) << "keeps no volume";
    const std::vector<profile::RankDropStep> order = profile::rankDropOrder(set);
    ASSERT_EQ(order.size(), 3u);
    EXPECT_EQ(order[0].volume, 1);
    EXPECT_EQ(order[1].volume, 2);
    EXPECT_EQ(order[2].volume, 0);
    EXPECT_EQ(order[2].keptBytes, 0u);
    EXPECT_EQ(order[0].keptBytes, bytes(0) + bytes(2));
    // The parse side of the form.
    EXPECT_EQ(profile::parseVolumeLod("rank_budget_mib:2.5").mode,
              profile::VolumeLod::Mode::RankBudgetMiB);
    EXPECT_THROW(profile::parseVolumeLod("rank_budget_mib:-1"), Error);
}

TEST(VolumeRanking, SidecarRoundTripsAndIsIgnoredWhenStale) {
    const std::filesystem::path dir = outputDir();
    const std::string probeFile = (dir / "set.pbp").string();
    probes::ProbeSet set = roomsProbes();
    const probes::VolumeRanks r = rank(set, {westWall()});
    probes::writeVolumeRanks(probes::volumeRanksPath(probeFile), r);
    probes::attachVolumeRanks(set, probeFile);
    ASSERT_TRUE(set.ranks.has_value()) << set.ranksNote;
    EXPECT_EQ(probes::volumeRanksJson(*set.ranks), probes::volumeRanksJson(r));

    probes::ProbeSet other = roomsProbes();
    other.inputHash = 0x9999; // re-baked
    probes::attachVolumeRanks(other, probeFile);
    EXPECT_FALSE(other.ranks.has_value());
    EXPECT_NE(other.ranksNote.find("stale"), std::string::npos) << other.ranksNote;

    probes::ProbeSet renamed = roomsProbes();
    renamed.volumes[2].name = "porch";
    EXPECT_NE(probes::volumeRanksProblem(r, renamed).find("'seen'"), std::string::npos);

    std::ofstream(probes::volumeRanksPath(probeFile)) << "{\"format\": \"something else\"}";
    probes::attachVolumeRanks(set, probeFile);
    EXPECT_FALSE(set.ranks.has_value());
    EXPECT_NE(set.ranksNote.find("not a volume ranks file"), std::string::npos) << set.ranksNote;
    EXPECT_THROW(profile::selectVolumes(set, profile::parseVolumeLod("rank_budget_mib:1")), Error);
}

} // namespace
} // namespace pb::test
