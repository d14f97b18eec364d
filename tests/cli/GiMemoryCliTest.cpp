// "GI memory" means one thing in bench and tune (issue 25, item 5; profile::kGiMemoryDefinition:
// probe textures + GI targets): bench's figure for a profile, counted from the frame it
// rendered, is the figure tune checks against --budget-mib for the same switches, estimated
// without GL. Before, bench counted the probe textures only.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// The JSON document a command printed on stdout (`--json` alone).
nlohmann::json runJson(const std::vector<std::string>& args, const fs::path& stdoutFile) {
    std::string out;
    const CommandResult r = runProbebenchSplit(args, stdoutFile.string(), out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(out);
}

} // namespace

TEST(GiMemoryCli, BenchReportsTheFigureTuneBudgets) {
    const fs::path dir = outputDir();
    const fs::path probes =
        bakeNestedRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_nested_tune_cli.pbp");
    const std::vector<std::string> size{"--width", "64", "--height", "36", "--frames", "1",
                                        "--warmup", "1"};
    std::vector<std::string> bench{"bench", "--scene", "rooms", "--probes", probes.string(),
                                   "--profiles", "handheld", "--rounds", "2", "--json"};
    bench.insert(bench.end(), size.begin(), size.end());
    const nlohmann::json bj = runJson(bench, dir / "bench.json");
    ASSERT_EQ(bj["profiles"].size(), 1u);
    const nlohmann::json& handheld = bj["profiles"][0];
    const double benchMiB = handheld["gi_memory_mib"].get<double>();
    // Targets are part of it: more than the probe textures.
    EXPECT_GT(benchMiB, handheld["gi_probe_memory_mib"].get<double>());

    std::vector<std::string> tune{"tune", "--scene", "rooms", "--probes", probes.string(),
                                  "--rounds", "1", "--base", "handheld", "--search", "gi.target_format",
                                  "--budget-ms", "1000", "--budget-mib", "100", "--out",
                                  (dir / "tuned.toml").string(), "--json"};
    tune.insert(tune.end(), size.begin(), size.end());
    const nlohmann::json tj = runJson(tune, dir / "tune.json");
    bool found = false;
    for (const auto& c : tj["candidates"])
        if (c["label"] == "base") { // handheld's own switches
            found = true;
            EXPECT_EQ(c["gi_memory_mib"].get<double>(), benchMiB) << c.dump();
        }
    EXPECT_TRUE(found) << "no tune candidate is the base";
}
