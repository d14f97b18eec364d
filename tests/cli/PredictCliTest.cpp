// The device model as a user runs it: `devices` lists the device files (a broken one is one line
// and the rest still listed), unknown devices are one line before any bake, and - where
// scripts/mesa-shim.sh has built the compilers - `predict` gives every profile's passes with a
// bound unit and each switch's delta, the same bits twice, and `bench --predict own` puts each
// profile on its own device beside the measured times. Without the compilers those tests skip,
// except under CI=true, where their absence is a failure.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace pb::test {
namespace {

namespace fs = std::filesystem;

bool predictCompilersBuilt() {
    return runCommand({(sourceDir() / "scripts/mesa-shim.sh").string(), "--print"}).exitCode == 0;
}

#define PREDICT_REQUIRE_COMPILERS()                                                                \
    do {                                                                                           \
        if (!predictCompilersBuilt()) {                                                            \
            if (underCi()) FAIL() << "the weak GPUs' compilers are not built under CI";            \
            GTEST_SKIP() << "the weak GPUs' compilers are not built (scripts/mesa-shim.sh)";       \
        }                                                                                          \
    } while (0)

const char* kPredictCamera = "0,1.5,0,1,1.2,1,60";

TEST(PredictCli, DevicesListsEveryDeviceFileAndABrokenOneIsOneLine) {
    const CommandResult r = runProbebench({"devices"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* d : {"switch-handheld", "switch-docked", "mali-g52-mc2", "mali-g57-mc2",
                          "adreno-618", "adreno-630", "gtx-1080", "xbox-one", "h200"})
        EXPECT_NE(r.output.find("| " + std::string(d) + " |"), std::string::npos) << d << r.output;
    std::string json;
    const fs::path out = outputDir();
    ASSERT_EQ(runProbebenchSplit({"devices", "--json"}, (out / "err.txt").string(), json).exitCode, 0);
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(j.contains("devices")) << json;
    EXPECT_GE(j["devices"].size(), 9u);

    const fs::path extra = out / "devices";
    fs::create_directories(extra);
    std::ofstream(extra / "broken.toml") << "name = \"broken\"\nlabel = \"x\"\n";
    const CommandResult b = runCommand({"env", "PROBEBENCH_DEVICES=" + extra.string(),
                                        binaryPath().string(), "devices"});
    EXPECT_EQ(b.exitCode, 1) << b.output;
    EXPECT_NE(b.output.find("broken.toml"), std::string::npos) << b.output;
    EXPECT_NE(b.output.find("| gtx-1080 |"), std::string::npos) << b.output;
}

TEST(PredictCli, AnUnknownDeviceIsOneLineBeforeAnyBake) {
    const fs::path out = outputDir();
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"predict", "--device", "switch-handhel", "--profiles", "handheld"},
          std::vector<std::string>{"bench", "--predict", "switch-handhel", "--profiles", "handheld"}}) {
        std::vector<std::string> a = args;
        a.insert(a.end(), {"--cache-dir", (out / "cache").string()});
        const CommandResult r = runProbebench(a);
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("did you mean 'switch-handheld'"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("baking"), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out / "cache")) << "it baked before saying so";
    }
}

TEST(PredictCli, EveryPassHasABoundUnitAndEachSwitchADeltaTheSameTwice) {
    PREDICT_REQUIRE_COMPILERS();
    const fs::path out = outputDir();
    const fs::path probes = bakeCoarseRooms(out / "rooms.probes");
    auto predict = [&](const std::string& name, std::string& json) {
        return runProbebenchSplit({"predict", "--scene", "rooms", "--device", "switch-docked,gtx-1080",
                                   "--profiles", "handheld", "--ablate", "--probes", probes.string(),
                                   "--camera", kPredictCamera, "--width", "160", "--height", "90",
                                   "--json"},
                                  (out / (name + ".err")).string(), json);
    };
    std::string first, second;
    const CommandResult r = predict("first", first);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_EQ(predict("second", second).exitCode, 0);
    EXPECT_EQ(first, second) << "the model is deterministic";
    const nlohmann::json j = nlohmann::json::parse(first, nullptr, false);
    ASSERT_TRUE(j.contains("device_model")) << first;
    ASSERT_EQ(j["device_model"].size(), 2u);
    for (const nlohmann::json& d : j["device_model"]) {
        EXPECT_EQ(d["model"], "model: " + d["device"].get<std::string>());
        const nlohmann::json& s = d["sessions"][0];
        EXPECT_EQ(s["profile"], "handheld");
        double apply = -1, fullApply = -1;
        for (const nlohmann::json& v : s["variants"]) {
            ASSERT_FALSE(v.contains("not_predicted")) << v.dump();
            EXPECT_GT(v["predicted_ms"].get<double>(), 0) << v["variant"];
            for (const nlohmann::json& p : v["passes"]) {
                EXPECT_TRUE(p["bound"].is_string()) << p.dump();
                if (p["pass"] != "gi-apply") continue;
                if (v["variant"] == "handheld") apply = p["predicted_ms"];
                if (v["variant"] == "handheld -gi.resolution") fullApply = p["predicted_ms"];
            }
        }
        // Half resolution evaluates a quarter of the pixels: its apply pass costs less.
        EXPECT_GT(apply, 0);
        EXPECT_GT(fullApply, apply) << d["device"];
        bool loops = false;
        for (const nlohmann::json& x : s["deltas"]) {
            EXPECT_TRUE(x["predicted_delta_ms"].is_number()) << x.dump();
            loops = loops || x["switch"] == "gi.loops";
        }
        EXPECT_TRUE(loops) << s.dump();
    }
}

TEST(PredictCli, BenchPutsEachProfileOnItsOwnDeviceBesideTheMeasuredTimes) {
    PREDICT_REQUIRE_COMPILERS();
    const fs::path out = outputDir();
    const fs::path probes = bakeCoarseRooms(out / "rooms.probes");
    const CommandResult r = runProbebench(
        {"bench", "--scene", "rooms", "--profiles", "handheld", "--probes", probes.string(),
         "--camera", kPredictCamera, "--width", "64", "--height", "36", "--rounds", "1", "--frames",
         "1", "--warmup", "1", "--no-floor", "--no-cache-model", "--predict", "own", "--json",
         (out / "b.json").string(), "--html", (out / "b.html").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("predicted ms (model: switch-handheld)"), std::string::npos) << r.output;
    std::ifstream in(out / "b.json");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(j.contains("device_model"));
    ASSERT_EQ(j["device_model"].size(), 1u);
    const nlohmann::json& s = j["device_model"][0]["sessions"][0];
    EXPECT_EQ(j["device_model"][0]["device"], "switch-handheld");
    EXPECT_EQ(s["own_device"], true);
    EXPECT_DOUBLE_EQ(s["budget_ms"].get<double>(), 33.3);
    EXPECT_EQ(s["own_size"], nlohmann::json({1280, 720}));
    EXPECT_GT(s["predicted_own_size_ms"].get<double>(), s["variants"][0]["predicted_ms"].get<double>());
    EXPECT_TRUE(s["variants"][0]["measured_ms"].is_number()) << s.dump();
    std::ifstream html(out / "b.html");
    const std::string text((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("model: switch-handheld"), std::string::npos);
}

TEST(PredictCli, TuneForADeviceUsesItsPredictedFrame) {
    const fs::path out = outputDir();
    const CommandResult bad = runProbebench(
        {"tune", "--base", "handheld", "--budget-ms", "30", "--budget-mib", "64", "--timing",
         "model:nosuch", "--out", (out / "bad.toml").string(), "--cache-dir", (out / "cache").string()});
    EXPECT_NE(bad.exitCode, 0) << bad.output;
    EXPECT_NE(bad.output.find("device 'nosuch'"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(out / "cache")) << "it baked before saying so";

    PREDICT_REQUIRE_COMPILERS();
    const fs::path probes = bakeCoarseRooms(out / "rooms.probes");
    const CommandResult r = runProbebench(
        {"tune", "--scene", "rooms", "--base", "handheld", "--search", "gi.resolution",
         "--budget-ms", "30", "--budget-mib", "64", "--timing", "model:switch-handheld",
         "--probes", probes.string(), "--camera", kPredictCamera, "--width", "64", "--height",
         "36", "--out", (out / "tuned.toml").string(), "--json", (out / "tune.json").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("frame ms: model: switch-handheld"), std::string::npos) << r.output;
    std::ifstream in(out / "tune.json");
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j["timing"].get<std::string>().rfind("model:switch-handheld", 0), 0u) << j["timing"];
    // The model is deterministic: the re-measure of the written profile predicts the same frame.
    EXPECT_NE(r.output.find("(+0.0%)"), std::string::npos) << r.output;
    std::ifstream toml(out / "tuned.toml");
    const std::string text((std::istreambuf_iterator<char>(toml)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("device: model:switch-handheld"), std::string::npos) << text;
}

} // namespace
} // namespace pb::test
