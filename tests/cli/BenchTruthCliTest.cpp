// `probebench bench --truth` as a user runs it: every profile, ablation variant and the
// reference measured against the path-traced truth, the truth's noise in the JSON, the report's
// side-by-side pictures, and a one-line error for --truth-spp 0.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

std::vector<std::string> tinyTruthBench(const fs::path& dir) {
    return {"bench", "--scene", "cornell", "--profiles", "handheld", "--ablate", "--width", "64",
            "--height", "36", "--rounds", "1", "--frames", "1", "--warmup", "1", "--no-floor",
            "--no-cache-model", "--truth", "--truth-spp", "8", "--cache-dir", (dir / "cache").string(),
            "--json", (dir / "out.json").string(), "--html", (dir / "report.html").string()};
}

std::string benchTruthReadText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

TEST(BenchTruthCli, EveryRowIsMeasuredAgainstTheTruthReferenceIncluded) {
    const fs::path dir = outputDir();
    auto r = runProbebench(tinyTruthBench(dir));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Against the path-traced truth"), std::string::npos) << r.output;
    auto j = nlohmann::json::parse(benchTruthReadText(dir / "out.json"));
    ASSERT_TRUE(j["truth"].is_object());
    EXPECT_EQ(j["truth"]["spp"], 8);
    ASSERT_EQ(j["truth"]["sizes"].size(), 1u);
    EXPECT_GT(j["truth"]["sizes"][0]["standard_error"].get<double>(), 0.0);
    ASSERT_GE(j["variants"].size(), 3u);
    for (const auto& v : j["variants"]) {
        ASSERT_TRUE(v["accuracy_vs_truth"].is_object()) << v["id"];
        // Nothing here is the truth: the reference included, every FLIP is above 0.
        EXPECT_GT(v["accuracy_vs_truth"]["flip_mean"].get<double>(), 0.0) << v["id"];
        EXPECT_GT(v["accuracy_vs_truth"]["relative_mse"].get<double>(), 0.0) << v["id"];
    }
    const auto& p = j["profiles"][0];
    EXPECT_TRUE(p["reference_accuracy_vs_truth"].is_object());
    // What convergence buys: the converged bench probes baked one pass short, the reference
    // rendered with them. The Cornell box's light needs several passes, so the last one shows.
    const auto& fewer = j["truth"]["fewer_bounce_passes"];
    ASSERT_TRUE(fewer["passes"].is_number()) << fewer.dump();
    EXPECT_GE(fewer["passes"].get<int>(), 3);
    EXPECT_EQ(fewer["baked_passes"].get<int>(), fewer["passes"].get<int>() - 1);
    EXPECT_TRUE(fewer["why_not"].is_null());
    const auto& split = p["truth_error_split"];
    ASSERT_TRUE(split["reference_one_pass_fewer_flip"].is_number()) << split.dump();
    EXPECT_GT(split["reference_one_pass_fewer_flip"].get<double>(), 0.0);
    EXPECT_NE(split["reference_one_pass_fewer_flip"].get<double>(), split["reference_flip"].get<double>());
    EXPECT_GT(split["reference_one_pass_fewer_relative_mse"].get<double>(), 0.0);
    // The Cornell box has no sun and no punctual light: no direct-light floor, and why.
    EXPECT_TRUE(j["truth"]["direct_light"]["why_not"].is_string()) << j["truth"].dump();
    EXPECT_TRUE(split["direct_light_flip"].is_null());
    EXPECT_NE(r.output.find("one bounce pass fewer (" + std::to_string(fewer["baked_passes"].get<int>()) +
                            " of " + std::to_string(fewer["passes"].get<int>()) + " passes)"),
              std::string::npos)
        << r.output;
    for (const char* k : {"truth", "reference", "profile", "reference_heatmap", "profile_heatmap"})
        EXPECT_TRUE(fs::exists(p["truth_pictures"][k].get<std::string>())) << k;
    const std::string html = benchTruthReadText(dir / "report.html");
    EXPECT_NE(html.find("Against the ground truth"), std::string::npos);
    EXPECT_NE(html.find("alt=\"truth\" src=\"data:image/png;base64,"), std::string::npos);
}

// Where the sun shines, the direct light's own error is measured: the frame without GI of the
// sun alone against its traced light (courtyard: a shadow-mapped sun over open ground).
TEST(BenchTruthCli, ASunlitSceneGetsTheDirectLightFloor) {
    const fs::path dir = outputDir();
    auto args = tinyTruthBench(dir);
    *(std::find(args.begin(), args.end(), "cornell")) = "courtyard";
    args.erase(std::find(args.begin(), args.end(), "--ablate"));
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto j = nlohmann::json::parse(benchTruthReadText(dir / "out.json"));
    const auto& direct = j["truth"]["direct_light"];
    ASSERT_TRUE(direct.contains("sizes")) << direct.dump();
    EXPECT_EQ(direct["max_depth"], 1);
    EXPECT_GT(direct["sizes"][0]["mean_luminance"].get<double>(), 0.0) << "the sun lights the ground";
    const auto& split = j["profiles"][0]["truth_error_split"];
    ASSERT_TRUE(split["direct_light_flip"].is_number()) << split.dump();
    // Not zero: a shadow map is not a shadow ray. Not the whole error either: the GI is missing.
    EXPECT_GT(split["direct_light_flip"].get<double>(), 0.0);
    EXPECT_LT(split["direct_light_flip"].get<double>(), 0.5);
    EXPECT_NE(r.output.find("At 64x36: The direct light alone"), std::string::npos) << r.output;
}

TEST(BenchTruthCli, TruthSppZeroIsAOneLineError) {
    const fs::path dir = outputDir();
    auto args = tinyTruthBench(dir);
    auto it = std::find(args.begin(), args.end(), "--truth-spp");
    *(it + 1) = "0";
    auto r = runProbebench(args);
    EXPECT_EQ(r.exitCode, 2) << "out of range: a usage error\n" << r.output;
    EXPECT_EQ(r.output.rfind("probebench: error: --truth-spp", 0), 0u) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
}
