// `probebench views`: coverage of the scene's views, the worst-case search (full coverage on
// a built-in scene, a camera that render accepts), --min-coverage as a gate, clean errors.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& courtyardProbes() {
    static const fs::path file = [] {
        fs::path f = fs::path(PB_TEST_OUTPUT_DIR) / "courtyard_views_cli.pbp";
        auto r = runProbebench({"bake", "--scene", "courtyard", "--rays", "16", "--bounces", "1",
                                "--out", f.string()});
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return f;
    }();
    return file;
}

} // namespace

TEST(ViewsCli, WorstCaseIsFullyCoveredAndRenderable) {
    auto r = runProbebench({"views", "--scene", "courtyard", "--probes", courtyardProbes().string(),
                            "--worst-case", "--width", "320", "--height", "180", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["worst_case"]["coverage"]["fraction"].get<double>(), 1.0);
    EXPECT_EQ(j["worst_case"]["coverage"]["width"].get<int>(), 320);
    EXPECT_GE(j["worst_case"]["coverage"]["max_overlap"].get<int>(), 1);
    // The printed camera is a --camera spec that render accepts.
    const std::string camera = j["worst_case"]["camera"];
    auto render =
        runProbebench({"render", "--scene", "courtyard", "--camera", camera, "--width", "64",
                       "--height", "36", "--out", (outputDir() / "worst_case.png").string()});
    EXPECT_EQ(render.exitCode, 0) << render.output;
}

TEST(ViewsCli, ListsEveryViewAndGatesOnCoverage) {
    auto r = runProbebench({"views", "--scene", "courtyard", "--probes", courtyardProbes().string(),
                            "--width", "64", "--height", "36"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* v : {"default", "overview", "courtyard", "interior"})
        EXPECT_NE(r.output.find(v), std::string::npos) << v << "\n" << r.output;
    // The overview sees sky: requiring full coverage of it fails with a clear message.
    auto gate = runProbebench({"views", "--scene", "courtyard", "--probes",
                               courtyardProbes().string(), "--view", "overview", "--width", "64",
                               "--height", "36", "--min-coverage", "1.0"});
    EXPECT_EQ(gate.exitCode, 1) << gate.output;
    EXPECT_NE(gate.output.find("below --min-coverage"), std::string::npos) << gate.output;
}

TEST(ViewsCli, BadInputIsAOneLineError) {
    auto missing = runProbebench({"views", "--scene", "courtyard", "--probes", "/nonexistent.pbp"});
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_FALSE(missing.crashed);
    EXPECT_NE(missing.output.find("/nonexistent.pbp"), std::string::npos) << missing.output;

    auto both = runProbebench({"views", "--scene", "courtyard", "--probes",
                               courtyardProbes().string(), "--worst-case", "--view", "overview"});
    EXPECT_NE(both.exitCode, 0);
    EXPECT_NE(both.output.find("--worst-case"), std::string::npos) << both.output;

    auto view = runProbebench({"views", "--scene", "courtyard", "--probes",
                               courtyardProbes().string(), "--view", "nosuch"});
    EXPECT_NE(view.exitCode, 0);
    EXPECT_NE(view.output.find("nosuch"), std::string::npos) << view.output;
}
