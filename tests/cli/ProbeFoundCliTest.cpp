// `probe` says what it found (issue 18, item 4): a lookup that reads no stored probe - outside
// every volume - reports "found": false with the reason, and prints no E as if it had been
// measured. A point in the middle of a room baked sparse is lit through stand-ins for its absent
// probes and says how many it read; the same point in a dense bake is found without any.
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
    if (storage == "sparse") EXPECT_NE(r.output.find("free space: "), std::string::npos) << r.output;
    return file;
}

nlohmann::json probeJson(const fs::path& probes, const std::string& at) {
    const CommandResult r = runProbebench(
        {"probe", "--probes", probes.string(), "--at", at, "--normal", "0,1,0", "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output, nullptr, false);
}
} // namespace

TEST(ProbeFoundCli, OutsideEveryVolumeIsSaidNotPrintedAsDarkness) {
    const fs::path sparse = bakeRooms(outputDir(), "sparse");
    const nlohmann::json j = probeJson(sparse, "50,50,50");
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], false) << j.dump();
    EXPECT_TRUE(j["irradiance"].is_null()) << j.dump();
    ASSERT_TRUE(j.contains("not_found")) << j.dump();
    EXPECT_NE(j["not_found"]["reason"].get<std::string>().find("outside every volume"),
              std::string::npos);

    const CommandResult text = runProbebench(
        {"probe", "--probes", sparse.string(), "--at", "50,50,50", "--normal", "0,1,0"});
    EXPECT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("E: none - no probe found: outside every volume"),
              std::string::npos)
        << text.output;
    EXPECT_EQ(text.output.find("E = "), std::string::npos) << text.output;
}

TEST(ProbeFoundCli, AMidRoomPointOfASparseBakeIsLitThroughStandIns) {
    const fs::path dir = outputDir();
    const fs::path sparse = bakeRooms(dir, "sparse");
    const std::string midAir = "-2,1.5,0"; // the sunlit room's centre: far from every surface
    const nlohmann::json j = probeJson(sparse, midAir);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], true) << j.dump();
    EXPECT_FALSE(j.contains("not_found")) << j.dump();
    EXPECT_GT(j["irradiance"][1].get<double>(), 0.0) << j.dump();
    EXPECT_GT(j["stand_ins"].get<int>(), 0) << j.dump();

    const CommandResult text = runProbebench(
        {"probe", "--probes", sparse.string(), "--at", midAir, "--normal", "0,1,0"});
    EXPECT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("stand-ins for absent probes"), std::string::npos) << text.output;

    // Stored dense, the same point reads only stored probes.
    const nlohmann::json dense = probeJson(bakeRooms(dir, "dense"), midAir);
    EXPECT_EQ(dense["found"], true) << dense.dump();
    EXPECT_EQ(dense["stand_ins"].get<int>(), 0) << dense.dump();
    EXPECT_GT(dense["irradiance"][1].get<double>(), 0.0) << dense.dump();
}

// Issue 18, `bake --free-space-irradiance`: the probes sparse storage leaves out keep their
// irradiance (irradiance-only), so a mid-room point reads them instead of stand-ins and gets
// the dense bake's light (15% is the bound); the summary and a file read back say so.
TEST(ProbeFoundCli, FreeSpaceIrradianceLightsAMidRoomPointLikeTheDenseBake) {
    const fs::path dir = outputDir();
    const fs::path file = dir / "rooms-irradiance.pbp";
    auto bake = [&](bool force) {
        std::vector<std::string> args{"bake",  "--scene",    "rooms",    "--volumes",
                                      "auto-uniform", "--spacing", "0.4", "--sparse",
                                      "--free-space-irradiance", "--rays", "32", "--bounces",
                                      "1", "--out", file.string()};
        if (force) args.push_back("--force");
        const CommandResult r = runProbebench(args);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return r.output;
    };
    for (bool force : {true, false}) { // baked, then read back: both split the probes
        const std::string out = bake(force);
        EXPECT_NE(out.find(" absent (no surface nearby: irradiance only, no visibility), "),
                  std::string::npos)
            << out;
        EXPECT_NE(out.find("absent probes keep their irradiance"), std::string::npos) << out;
    }
    const std::string midAir = "-2,1.5,0";
    const nlohmann::json j = probeJson(file, midAir);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["found"], true) << j.dump();
    EXPECT_GT(j["irradiance_only"].get<int>(), 0) << j.dump();
    EXPECT_EQ(j["stand_ins"].get<int>(), 0) << j.dump();
    const CommandResult text =
        runProbebench({"probe", "--probes", file.string(), "--at", midAir, "--normal", "0,1,0"});
    EXPECT_NE(text.output.find("irradiance-only: no surface nearby"), std::string::npos)
        << text.output;

    const nlohmann::json dense = probeJson(bakeRooms(dir, "dense"), midAir);
    const double d = dense["irradiance"][1].get<double>(), s = j["irradiance"][1].get<double>();
    EXPECT_GT(d, 0.0) << dense.dump();
    EXPECT_NEAR(s, d, 0.15 * d) << "sparse " << j.dump() << "\ndense " << dense.dump();

    // Without sparse storage there is nothing to keep: a one-line error, no file.
    const fs::path none = dir / "rooms-irradiance-dense.pbp";
    fs::remove(none);
    const CommandResult bad = runProbebench({"bake", "--scene", "rooms", "--volumes",
                                             "auto-uniform", "--free-space-irradiance", "--out",
                                             none.string()});
    EXPECT_NE(bad.exitCode, 0) << bad.output;
    EXPECT_EQ(bad.output.rfind("probebench: error: --free-space-irradiance", 0), 0u) << bad.output;
    EXPECT_EQ(bad.output.find('\n'), bad.output.size() - 1) << bad.output;
    EXPECT_FALSE(fs::exists(none));
}
