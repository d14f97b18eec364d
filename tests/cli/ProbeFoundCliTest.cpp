// `probe` says what it found (issue 18, item 4): a point that no stored probe reaches - mid-air
// in a room baked sparse - reports "found": false with the reason and the corners' state,
// and prints no E as if it had been measured; a point on the floor of the same bake, and the
// same mid-air point in a dense bake, are found.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {
// dir: the test's outputDir(), taken once (each call empties it).
fs::path bakeRooms(const fs::path& dir, const std::string& storage) {
    const fs::path file = dir / ("rooms-" + storage + ".pbp");
    const CommandResult r = runProbebench({"bake", "--scene", "rooms", "--volumes",
                                           "auto-uniform", "--spacing", "0.4", "--" + storage,
                                           "--rays", "32", "--bounces", "1", "--out",
                                           file.string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return file;
}

nlohmann::json probeJson(const fs::path& probes, const std::string& at) {
    const CommandResult r = runProbebench(
        {"probe", "--probes", probes.string(), "--at", at, "--normal", "0,1,0", "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output, nullptr, false);
}
} // namespace

TEST(ProbeFoundCli, AMidAirPointBetweenSparseProbesIsReportedAsNotFound) {
    const fs::path dir = outputDir();
    const fs::path sparse = bakeRooms(dir, "sparse");
    const std::string midAir = "-2,1.3,0.1"; // the sunlit room's centre, 1.3 m up
    const nlohmann::json j = probeJson(sparse, midAir);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], false) << j.dump();
    EXPECT_TRUE(j["irradiance"].is_null()) << j.dump();
    ASSERT_TRUE(j.contains("not_found")) << j.dump();
    EXPECT_GT(j["not_found"]["corners_not_stored"].get<int>(), 0) << j.dump();
    EXPECT_NE(j["not_found"]["reason"].get<std::string>().find("not stored"), std::string::npos);

    const CommandResult text = runProbebench(
        {"probe", "--probes", sparse.string(), "--at", midAir, "--normal", "0,1,0"});
    EXPECT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("E: none - no probe found"), std::string::npos) << text.output;
    EXPECT_EQ(text.output.find("E = "), std::string::npos) << text.output;

    // The floor below it is a surface: its cell's probes are stored.
    const nlohmann::json floor = probeJson(sparse, "-2,0.01,0.1");
    EXPECT_EQ(floor["found"], true) << floor.dump();
    EXPECT_TRUE(floor["irradiance"].is_array());
    EXPECT_FALSE(floor.contains("not_found"));
    // Stored dense, the mid-air point is found and lit.
    const nlohmann::json dense = probeJson(bakeRooms(dir, "dense"), midAir);
    EXPECT_EQ(dense["found"], true) << dense.dump();
    EXPECT_GT(dense["irradiance"][1].get<double>(), 0.0) << dense.dump();

    // Outside every volume: not found either, for that reason.
    const nlohmann::json outside = probeJson(sparse, "50,50,50");
    EXPECT_EQ(outside["found"], false);
    EXPECT_NE(outside["not_found"]["reason"].get<std::string>().find("outside every volume"),
              std::string::npos);
}
