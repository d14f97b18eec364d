// `probebench tune --truth`: the search's accuracy is FLIP against the path-traced truth, so no
// candidate - not even the one equal to the reference - measures 0, and the JSON says so.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

TEST(TuneTruthCli, OptimisesAgainstTheTruth) {
    const fs::path dir = outputDir();
    auto r = runProbebench({"tune", "--scene", "cornell", "--base", "reference", "--width", "64", "--height", "36",
                            "--rounds", "1", "--frames", "1", "--warmup", "1", "--search", "gi.resolution",
                            "--budget-ms", "1000", "--budget-mib", "1000", "--truth", "--truth-spp", "8",
                            "--cache-dir", (dir / "cache").string(), "--out", (dir / "t.toml").string(),
                            "--json", (dir / "t.json").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream toml(dir / "t.toml");
    const std::string written((std::istreambuf_iterator<char>(toml)), std::istreambuf_iterator<char>());
    EXPECT_NE(written.find("vs the path-traced truth (8 spp)"), std::string::npos) << written;
    std::ifstream in(dir / "t.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["accuracy_target"], "truth");
    EXPECT_EQ(j["truth"]["spp"], 8);
    int measured = 0;
    for (const auto& c : j["candidates"]) {
        if (!c["measured"].get<bool>()) continue;
        ++measured;
        EXPECT_GT(c["flip"].get<double>(), 0.0) << c["label"]; // the reference itself included
    }
    EXPECT_GE(measured, 2);
}
