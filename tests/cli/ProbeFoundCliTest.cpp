// `probebench probe` says what it found (issue 18, item 4): a lookup that read no stored probe
// is no measurement, so it prints why instead of E = 0 (JSON: "found": false, the reason and
// no irradiance); a sparse bake lights a point in the middle of a room through stand-ins for
// its absent probes and says how many it read.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// A quick sparse bake of rooms: auto-uniform stores dense unless --sparse.
fs::path bakeSparseRooms() {
    const fs::path file = outputDir() / "rooms_sparse.pbp";
    const CommandResult r = runProbebench(
        {"bake", "--scene", "rooms", "--volumes", "auto-uniform", "--spacing", "0.4", "--sparse",
         "--rays", "32", "--bounces", "1", "--out", file.string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("free space: "), std::string::npos) << r.output;
    return file;
}

nlohmann::json probeJson(const fs::path& probes, const std::string& at) {
    const CommandResult r = runProbebench(
        {"probe", "--probes", probes.string(), "--at", at, "--normal", "0,1,0", "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output.substr(std::min(r.output.find('{'), r.output.size())),
                                 nullptr, false);
}

} // namespace

TEST(ProbeFoundCli, NoProbeIsSaidNotPrintedAsDarkness) {
    const fs::path probes = bakeSparseRooms();
    const nlohmann::json j = probeJson(probes, "100,100,100");
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], false) << j.dump();
    EXPECT_EQ(j["reason"], "outside every volume") << j.dump();
    EXPECT_TRUE(j["irradiance"].is_null()) << j.dump();

    const CommandResult text = runProbebench(
        {"probe", "--probes", probes.string(), "--at", "100,100,100", "--normal", "0,1,0"});
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("no stored probe found: outside every volume"), std::string::npos)
        << text.output;
    EXPECT_EQ(text.output.find("E = "), std::string::npos) << text.output;
}

TEST(ProbeFoundCli, MidRoomPointOfASparseBakeIsLitThroughStandIns) {
    const fs::path probes = bakeSparseRooms();
    // The sunlit room's centre, 1.5 m up: far from every surface at a 0.4 m spacing.
    const nlohmann::json j = probeJson(probes, "-2,1.5,0");
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], true) << j.dump();
    EXPECT_FALSE(j.contains("reason")) << j.dump();
    EXPECT_GT(j["irradiance"][1].get<double>(), 0.0) << j.dump();
    EXPECT_GT(j["stand_ins"].get<int>(), 0) << j.dump();
}
