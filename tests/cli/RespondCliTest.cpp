// `probebench respond` (issue 20): a tiny run's JSON and report, and the bad inputs that must
// fail in one line before anything renders.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& respondCoarseRooms() {
    static const fs::path file =
        bakeCoarseRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_coarse_respond.pbp");
    return file;
}

std::vector<std::string> respond(const fs::path& dir, std::vector<std::string> extra) {
    std::vector<std::string> args = {"respond",
                                     "--scene",
                                     "rooms",
                                     "--probes",
                                     respondCoarseRooms().string(),
                                     "--width",
                                     "64",
                                     "--height",
                                     "36",
                                     "--rays-per-update",
                                     "64",
                                     "--sample-bakes",
                                     "8",
                                     "--cache-dir",
                                     (dir / "cache").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

std::string respondReadText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// t95 as a number; a schedule that never settled counts as slower than any that did.
double settled(const nlohmann::json& v) {
    return v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
}

// The first frame from which the error curve stays within `tolerance` (infinity: never).
double settleAt(const nlohmann::json& curve, double tolerance) {
    double frame = std::numeric_limits<double>::infinity();
    for (int n = int(curve.size()) - 1; n >= 0 && curve[std::size_t(n)].get<double>() <= tolerance;
         --n)
        frame = n;
    return frame;
}

} // namespace

TEST(RespondCli, MeasuresEveryScheduleAgainstTheConvergedRebake) {
    const fs::path dir = outputDir();
    auto r = runProbebench(
        respond(dir, {"--event", "sun:off@2", "--frames", "60", "--json", (dir / "r.json").string(),
                      "--out-dir", (dir / "out").string()}));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(respondReadText(dir / "r.json"));
    ASSERT_EQ(j["schedules"].size(), 3u);
    std::map<std::string, nlohmann::json> by;
    for (const auto& s : j["schedules"]) {
        for (const char* key :
             {"t95_frames", "t99_frames", "overshoot", "flicker", "far_drift", "rays_per_frame",
              "cpu_ms_per_frame", "bytes_uploaded", "error_curve"})
            EXPECT_TRUE(s.contains(key)) << s["schedule"] << " lacks " << key;
        // 58 frames after the event plus frame 0 (before any update).
        EXPECT_EQ(s["error_curve"].size(), 59u);
        EXPECT_DOUBLE_EQ(s["error_curve"][0].get<double>(), 1.0);
        // Only changed tiles go up: whole 8x8 RGBA16F tiles (512 bytes), some every frame.
        const auto bytes = s["bytes_uploaded"].get<std::uint64_t>();
        EXPECT_GT(bytes, 0u);
        EXPECT_EQ(bytes % 512u, 0u);
        EXPECT_GT(s["rays_per_frame"].get<double>(), 0.0);
        by[s["schedule"]] = s;
    }
    // The hastened schedule reaches the changed lighting no later than plain hysteresis, and
    // every schedule moved towards it. (This coarse 32-ray file's reference leaves a noise
    // floor near 20% of the step, so the test compares the settle within 30%, not 5%.)
    EXPECT_LE(settled(by["hastened"]["t95_frames"]), settled(by["hysteresis"]["t95_frames"]));
    EXPECT_LT(settleAt(by["hastened"]["error_curve"], 0.3),
              settleAt(by["hysteresis"]["error_curve"], 0.3) / 3.0);
    for (const auto& [name, s] : by)
        EXPECT_LT(s["final_error"].get<double>(), 0.6) << name;
    // Hysteresis decays like 0.97^n while the step is well above the noise floor.
    const auto& hy = by["hysteresis"]["error_curve"];
    for (std::size_t n = 0; n <= 12; ++n)
        EXPECT_NEAR(hy[n].get<double>(), std::pow(0.97, double(n)), 0.05) << n;
    EXPECT_TRUE(j["closed_form_hysteresis"].is_array());
    const std::string html = respondReadText(dir / "out" / "report.html");
    EXPECT_NE(html.find("<svg"), std::string::npos);
    EXPECT_NE(html.find("<polyline"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "out" / "frames" / "hastened_0059.png"));
}

TEST(RespondCli, BadEventsAndForeignProbesFailInOneLineBeforeRendering) {
    const fs::path dir = outputDir();
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"--event", "light:nolamp:off@1", "--frames", "10"}, "has no light 'nolamp'"},
        {{"--event", "node:nothing:remove@1", "--frames", "10"}, "has no static node 'nothing'"},
        {{"--event", "sun:off@10", "--frames", "10"}, "outside the run"},
        {{"--event", "sun:dim@1", "--frames", "10"}, "--event 'sun:dim@1'"},
        {{"--event", "sun:off@1", "--frames", "10", "--schedule", "fast"}, "unknown schedule"},
    };
    for (const Case& c : cases) {
        auto r = runProbebench(respond(dir, c.args));
        EXPECT_NE(r.exitCode, 0) << c.message;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("searching the worst-case view"), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
    // Probes baked for rooms, given with cornell: a hash mismatch.
    std::vector<std::string> args = respond(dir, {"--event", "sun:off@1", "--frames", "10"});
    args[2] = "cornell";
    auto r = runProbebench(args);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("another scene"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("searching the worst-case view"), std::string::npos) << r.output;
}

TEST(RespondCli, BudgetsCapTheUpdatesAndTheUploadedBytes) {
    const fs::path dir = outputDir();
    // 100 tiles of 512 bytes; the ray budget (64 rays x 1 bounce per update) allows 200.
    auto r = runProbebench(
        respond(dir, {"--event", "sun:off@1", "--frames", "6", "--schedule", "hastened",
                      "--upload-bytes-per-frame", "51200", "--rays-per-frame", "12800", "--json",
                      (dir / "b.json").string()}));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(respondReadText(dir / "b.json"));
    EXPECT_EQ(j["probe_updates_per_frame_budget"].get<int>(), 100);
    const auto& s = j["schedules"][0];
    EXPECT_DOUBLE_EQ(s["probe_updates_per_frame"].get<double>(), 100.0);
    EXPECT_DOUBLE_EQ(s["upload_bytes_per_frame"].get<double>(), 51200.0);
    EXPECT_LE(s["rays_per_frame"].get<double>(), 12800.0);
}

TEST(RespondCli, AProfileCarriesTheUpdateBudget) {
    const fs::path dir = outputDir();
    const fs::path profile = dir / "budgeted.toml";
    std::ofstream(profile) << "inherit = \"handheld\"\n[update]\nrays_per_frame = 12800\n"
                              "upload_bytes_per_frame = 51200\n";
    auto r = runProbebench(
        respond(dir, {"--event", "sun:off@1", "--frames", "4", "--schedule", "hastened",
                      "--profile", profile.string(), "--json", (dir / "p.json").string()}));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(respondReadText(dir / "p.json"));
    EXPECT_EQ(j["rays_per_frame_budget"].get<int>(), 12800);
    EXPECT_EQ(j["probe_updates_per_frame_budget"].get<int>(), 100);
    // The command line wins over the profile.
    auto cli = runProbebench(
        respond(dir, {"--event", "sun:off@1", "--frames", "4", "--schedule", "hastened",
                      "--profile", profile.string(), "--upload-bytes-per-frame", "5120", "--json",
                      (dir / "q.json").string()}));
    ASSERT_EQ(cli.exitCode, 0) << cli.output;
    EXPECT_EQ(
        nlohmann::json::parse(respondReadText(dir / "q.json"))["probe_updates_per_frame_budget"]
            .get<int>(),
        10);
}
