// `probebench tune` on a built-in scene at a tiny size with one round: it respects its budgets
// (a GI memory budget that leaves out every RGBA32F-target configuration, the reference's
// included; the time budget is generous so no assertion depends on a timing), the written
// profile loads and renders, the re-measurement reproduces the deterministic figures, and an
// impossible budget fails with one line and writes nothing. The search's choice under a time
// budget that excludes full resolution is tested without timings in tests/unit/TuneTest.cpp.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& nestedProbes() {
    static const fs::path file =
        bakeNestedRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_nested_tune_cli.pbp");
    return file;
}

// GPU bytes of every probe volume (probebench volumes --json).
double probeMiB() {
    auto r = runProbebench({"volumes", "--probes", nestedProbes().string(), "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    double bytes = 0;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    for (const auto& v : j["volumes"])
        bytes += v["bytes"].get<double>();
    return bytes / (1024.0 * 1024.0);
}

std::vector<std::string> tuneArgs(const fs::path& out, const std::string& budgetMib) {
    return {"tune",
            "--scene",
            "rooms",
            "--probes",
            nestedProbes().string(),
            "--width",
            "64",
            "--height",
            "36",
            "--rounds",
            "1",
            "--frames",
            "1",
            "--warmup",
            "1",
            "--search",
            "gi.resolution,gi.target_format",
            "--budget-ms",
            "1000",
            "--budget-mib",
            budgetMib,
            "--out",
            out.string()};
}

} // namespace

TEST(TuneCli, RespectsItsBudgetsAndWritesAProfileThatLoads) {
    const fs::path dir = outputDir();
    // 64x36: an RGBA32F target alone is 36864 bytes, RGBA16F at full resolution 18432, at half
    // 4608 + an 18432 upsample target. 30000 bytes over the probes leave out every RGBA32F one.
    const double budget = probeMiB() + 30000.0 / (1024.0 * 1024.0);
    auto args = tuneArgs(dir / "profiles" / "tuned.toml", std::to_string(budget));
    // profiles/ does not exist yet: --mkdir asks for it (the one output-folder rule).
    args.insert(args.end(), {"--json", (dir / "tune.json").string(), "--mkdir"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Pareto front"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("tune: session 1"), std::string::npos) << "progress on stderr";
    EXPECT_NE(r.output.find("FLIP and memory identical"), std::string::npos) << r.output;

    std::ifstream in(dir / "tune.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["method"], "exhaustive");
    EXPECT_EQ(j["context"]["debug_context"], false) << "timed in a non-debug context (issue 25)";
    ASSERT_FALSE(j["chosen"].is_null());
    int measured = 0, overMemory = 0;
    for (const auto& c : j["candidates"]) {
        const bool rgba32f = c["switches"]["gi.target_format"] == "rgba32f";
        EXPECT_EQ(c["gi_memory_mib"].get<double>() > budget, rgba32f) << c["label"];
        if (rgba32f) {
            ++overMemory;
            EXPECT_FALSE(c["measured"].get<bool>()) << "over the memory budget: never rendered";
        }
        if (c["label"] == j["chosen"]) {
            EXPECT_TRUE(c["fits"].get<bool>());
            EXPECT_LE(c["gi_memory_mib"].get<double>(), budget);
            EXPECT_LE(c["frame_ms"].get<double>(), 1000.0);
            EXPECT_EQ(c["flip"].get<double>(), j["remeasure"]["flip"].get<double>());
            EXPECT_EQ(c["gi_memory_mib"].get<double>(), j["remeasure"]["gi_memory_mib"].get<double>());
        }
        measured += c["measured"].get<bool>();
    }
    EXPECT_EQ(overMemory, 3);
    EXPECT_EQ(measured, 6);
    EXPECT_FALSE(j["pareto"].empty());

    // The written profile loads (inheriting the base) and renders.
    auto show = runProbebench({"profiles", "--show", (dir / "profiles" / "tuned.toml").string()});
    ASSERT_EQ(show.exitCode, 0) << show.output;
    EXPECT_NE(show.output.find("inherits reference"), std::string::npos) << show.output;
    auto render = runProbebench({"render", "--scene", "rooms", "--probes", nestedProbes().string(),
                                 "--profile", (dir / "profiles" / "tuned.toml").string(), "--out",
                                 (dir / "tuned.png").string()});
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find("rendered 64x36"), std::string::npos) << render.output;
}

TEST(TuneCli, AnImpossibleBudgetFailsWithOneLineAndWritesNothing) {
    const fs::path dir = outputDir();
    auto r = runProbebench(tuneArgs(dir / "never.toml", "0.001"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(r.output.rfind("probebench: error: tune: nothing fits 1000 ms and 0.001 MiB", 0), 0u)
        << r.output;
    EXPECT_NE(r.output.find("closest: "), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "never.toml"));

    auto bad = runProbebench(tuneArgs(dir / "x.txt", "4"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.output.find("--out"), std::string::npos) << bad.output;
}
