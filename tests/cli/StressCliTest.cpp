// `probebench stress` as a user runs it: the JSON it writes on a tiny sweep, the table, and
// one-line errors for bad options (nothing written).
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <fstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {
std::vector<std::string> tiny(std::vector<std::string> extra) {
    std::vector<std::string> args{"stress", "--width", "16", "--height", "12", "--rays", "8"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}
} // namespace

TEST(StressCli, WritesTheSweepAsJson) {
    const fs::path out = outputDir() / "stress.json";
    auto r = runProbebench(
        tiny({"--cases", "light=1e+06,grid=1x1x1", "--variant",
              "fp16:gi.precision=fp16,probes.format=rgba32f", "--json", out.string()}));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("fp16/off"), std::string::npos) << r.output; // the table
    EXPECT_NE(r.output.find("[2/2] grid=1x1x1"), std::string::npos) << "progress: " << r.output;
    std::ifstream in(out);
    ASSERT_TRUE(in) << out;
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["command"], "stress");
    ASSERT_EQ(j["cases"].size(), 2u);
    EXPECT_EQ(j["cases"][0]["name"], "light=1e+06");
    EXPECT_EQ(j["cases"][0]["width"], 16);
    ASSERT_EQ(j["runs"].size(), 4u); // 2 cases x (guards as given, off)
    for (const auto& run : j["runs"]) {
        EXPECT_TRUE(run["symptom"].is_string());
        EXPECT_TRUE(run["nonfinite_pixels"].is_number_integer());
        EXPECT_TRUE(run["culprits"].is_array());
        EXPECT_TRUE(run["fixed_by"].is_array());
    }
    // light=1e6 in fp16 without guards overflows; the sweep names the guard that fixes it.
    const auto& off = j["runs"][1];
    EXPECT_EQ(off["guards"], "off");
    EXPECT_EQ(off["symptom"], "nan/inf");
    // Among the culprits (the rgba16f target may overflow too: which breaks first follows the
    // bake's last bits).
    const std::vector<std::string> culprits = off["culprits"].get<std::vector<std::string>>();
    EXPECT_NE(std::find(culprits.begin(), culprits.end(), "gi.precision=fp16"), culprits.end())
        << off["culprits"].dump();
    EXPECT_EQ(off["fixed_by"][0], "gi.guard_exposure=on");
    EXPECT_EQ(j["summary"]["nonfinite_with_guards"], 0);
    EXPECT_TRUE(j["platform"].is_string());
}

TEST(StressCli, SweepsPlatformProfilesWithTheirSwitches) {
    const fs::path out = outputDir() / "stress_profiles.json";
    auto r = runProbebench(tiny({"--cases", "hot_spot", "--profiles", "handheld,reference",
                                 "--guards", "as_given", "--json", out.string()}));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(out);
    ASSERT_TRUE(in) << out;
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["runs"].size(), 2u); // one case x two profiles, guards as the profiles give them
    EXPECT_EQ(j["runs"][0]["variant"], "handheld");
    EXPECT_EQ(j["runs"][1]["variant"], "reference");
    auto bad = runProbebench(tiny({"--profiles", "no-such-profile"}));
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("no-such-profile"), std::string::npos) << bad.output;
}

TEST(StressCli, ListsItsCases) {
    auto r = runProbebench({"stress", "--list-cases"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name :
         {"light=1e-06", "spacing=1000", "offset=1e+06", "thin_wall", "grid=2x1x1", "rays=1",
          "resolution=1x1", "bad_normals", "variance_zero", "fold_edges", "all_invalid"})
        EXPECT_NE(r.output.find(name), std::string::npos) << name;
}

TEST(StressCli, BadOptionsAreOneLineErrors) {
    const fs::path out = outputDir() / "never.json";
    struct Case {
        std::vector<std::string> args;
        std::string mustName;
    };
    const std::vector<Case> cases = {
        {{"--variant", "fp16:gi.precision=fp8"}, "fp32, fp16"},
        {{"--variant", ":gi.precision=fp16"}, "expected NAME"},
        {{"--variant", "a:gi.precision"}, "is not key=value"},
        {{"--variant", "a:probes.format=bc7"}, "bc7"},
        {{"--variant", "a", "--variant", "a"}, "used twice"},
        {{"--set", "gi.nope=1"}, "unknown switch 'gi.nope'"},
        {{"--cases", "lihgt"}, "no case or group 'lihgt'"},
        {{"--guards", "sometimes"}, "as_given, off, both"},
        {{"--threshold", "-1"}, "--threshold"},
        {{"--width", "0"}, "--width"},
        {{"--rays", "0"}, "--rays"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"stress", "--json", out.string()};
        args.insert(args.end(), c.args.begin(), c.args.end());
        auto r = runProbebench(args);
        EXPECT_NE(r.exitCode, 0) << c.mustName;
        EXPECT_FALSE(r.crashed) << c.mustName;
        EXPECT_EQ(r.output.rfind("probebench: error: ", 0), 0u) << r.output;
        EXPECT_NE(r.output.find(c.mustName), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(fs::exists(out)) << "nothing written on error";
    }
}
