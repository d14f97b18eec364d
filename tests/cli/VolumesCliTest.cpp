// `probebench volumes [--rank [--write-ranks]]` and gi.volume_lod=rank_budget_mib on `render`:
// on `rooms` with a volume per room nested in one over the house, the sunlit room's own view
// ranks its room's volume above the dark room's, and a budget for one child keeps that one.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// Its own copy per test: --write-ranks puts a sidecar next to it.
fs::path bakeNested(const fs::path& dir) {
    return bakeNestedRooms(dir / "rooms_nested.pbp");
}

nlohmann::json parseJson(const std::string& output) {
    const size_t begin = output.find('{'), end = output.rfind('}'); // stderr lines around it
    return nlohmann::json::parse(output.substr(begin, end + 1 - begin));
}

} // namespace

TEST(VolumesCli, RankOrdersByLostAccuracyAndBudgetKeepsTheValuableChild) {
    const fs::path dir = outputDir();
    const fs::path probes = bakeNested(dir);
    auto list = runProbebench({"volumes", "--probes", probes.string()});
    ASSERT_EQ(list.exitCode, 0) << list.output;
    EXPECT_NE(list.output.find("sunlit_room"), std::string::npos) << list.output;
    EXPECT_NE(list.output.find("ranks: no ranks file"), std::string::npos) << list.output;

    auto ranked = runProbebench({"volumes", "--scene", "rooms", "--probes", probes.string(),
                                 "--rank", "--views", "sunlit_room", "--width", "96", "--height",
                                 "54", "--json", "--write-ranks"});
    ASSERT_EQ(ranked.exitCode, 0) << ranked.output;
    const nlohmann::json j = parseJson(ranked.output);
    std::map<std::string, nlohmann::json> byName;
    for (const auto& v : j["volumes"])
        byName[v["name"]] = v;
    ASSERT_EQ(byName.size(), 3u);
    EXPECT_GT(byName["sunlit_room"]["loss"].get<double>(),
              byName["dark_room"]["loss"].get<double>());
    // The house with its children omitted leaves every pixel to the ambient, which in this
    // closed house is nearly black (the sky share its surfaces see, SkyVisibility.h): the loss is
    // about all of the indirect light, a relative MSE near 1. (With the old fixed pi/4 sky
    // ambient it was several times that, and ranked the house first.)
    EXPECT_GT(byName["house"]["loss"].get<double>(), 0.8);
    EXPECT_LT(byName["house"]["loss"].get<double>(), 1.05);
    EXPECT_EQ(j["drop_order"][0]["volume"], "dark_room");
    ASSERT_TRUE(fs::exists(probes.string() + ".ranks.json"));

    // A budget for the house and one child keeps the sunlit room's.
    const std::uint64_t budgetBytes = j["drop_order"][0]["kept_bytes"].get<std::uint64_t>();
    const std::string budget = std::to_string(double(budgetBytes) / (1024.0 * 1024.0) + 1e-4);
    auto render = runProbebench({"render", "--scene", "rooms", "--view", "sunlit_room", "--width",
                                 "64", "--height", "36", "--probes", probes.string(), "--set",
                                 "gi.volume_lod=rank_budget_mib:" + budget, "--verbose", "--out",
                                 (dir / "r.png").string()});
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find("gi: ddgi, 2 of 3 volume(s)"), std::string::npos) << render.output;
    EXPECT_NE(render.output.find("skipped volume 'dark_room'"), std::string::npos) << render.output;
}

TEST(VolumesCli, RankBudgetWithoutRanksIsAOneLineError) {
    const fs::path dir = outputDir();
    const fs::path probes = bakeNested(dir);
    auto r = runProbebench({"render", "--scene", "rooms", "--width", "32", "--height", "18",
                            "--probes", probes.string(), "--set", "gi.volume_lod=rank_budget_mib:1",
                            "--out", (dir / "x.png").string()});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(
        r.output.rfind("probebench: error: gi.volume_lod=rank_budget_mib:1: no volume ranks", 0),
        0u)
        << r.output;
    EXPECT_NE(r.output.find("probebench volumes --rank --write-ranks"), std::string::npos);
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.png"));

    auto bad = runProbebench({"volumes", "--probes", probes.string(), "--write-ranks"});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.output.find("--write-ranks: needs --rank"), std::string::npos) << bad.output;
}
