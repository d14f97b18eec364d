// `probebench bench --respond` (issue 20, item 4): a tiny bench of two profiles, one with an
// [update] budget, records per profile and schedule respond's response figures beside the
// frame times; a bad event is a one-line error before anything is timed.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& coarseRooms() {
    static const fs::path file =
        bakeCoarseRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_coarse_bench_respond.pbp");
    return file;
}

std::string benchRespondReadText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

constexpr long long kBudgetBytes = 1024; // two 8x8 rgba16f tiles a frame
constexpr int kFrames = 12;

// The reference profile with a tight [update] budget: few rays and two tiles a frame.
fs::path budgetedProfile(const fs::path& dir) {
    fs::path p = dir / "slow-updates.toml";
    std::ofstream(p) << "inherit = \"reference\"\ndescription = \"reference, tight updates\"\n"
                        "[update]\nrays_per_frame = 1\nupload_bytes_per_frame = "
                     << kBudgetBytes << "\n";
    return p;
}

std::vector<std::string> benchRespondTinyBench(const fs::path& dir, const std::string& event) {
    return {"bench",
            "--scene",
            "rooms",
            "--probes",
            coarseRooms().string(),
            "--profiles",
            "reference," + budgetedProfile(dir).string(),
            "--width",
            "32",
            "--height",
            "18",
            "--rounds",
            "1",
            "--frames",
            "1",
            "--warmup",
            "1",
            "--no-floor",
            "--no-cache-model",
            "--cache-dir",
            (dir / "cache").string(),
            "--respond",
            event,
            "--respond-frames",
            std::to_string(kFrames),
            "--json",
            (dir / "out.json").string(),
            "--html",
            (dir / "report.html").string()};
}

} // namespace

TEST(BenchRespondCli, RecordsEachProfilesResponseWithItsUpdateBudget) {
    const fs::path dir = outputDir();
    auto r = runProbebench(benchRespondTinyBench(dir, "sun:off@2"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(benchRespondReadText(dir / "out.json"));
    ASSERT_TRUE(j.contains("response")) << j.dump();
    const auto& resp = j["response"];
    EXPECT_EQ(resp["frames"], kFrames);
    EXPECT_EQ(resp["width"], 32);
    ASSERT_EQ(resp["profiles"].size(), j["profiles"].size());
    ASSERT_EQ(resp["profiles"].size(), 2u);
    const double raysPerUpdate = resp["rays_per_update"].get<double>();
    ASSERT_GT(raysPerUpdate, 0.0);
    std::map<std::string, nlohmann::json> by;
    for (const auto& p : resp["profiles"]) {
        ASSERT_EQ(p["schedules"].size(), 3u) << p.dump();
        by[p["profile"].get<std::string>()] = p;
        for (const auto& s : p["schedules"]) {
            // Settled within the frames after the event, or never (null).
            for (const char* t : {"t95_frames", "t99_frames"}) {
                ASSERT_TRUE(s.contains(t));
                if (!s[t].is_null()) {
                    EXPECT_GE(s[t].get<int>(), 0);
                    EXPECT_LE(s[t].get<int>(), kFrames - 2) << s.dump();
                }
            }
            if (!s["t95_frames"].is_null() && !s["t99_frames"].is_null()) {
                EXPECT_LE(s["t95_frames"].get<int>(), s["t99_frames"].get<int>());
            }
            EXPECT_FALSE(s.contains("error_curve")) << "curves stay in respond's own JSON";
            EXPECT_GT(s["rays_per_frame"].get<double>(), 0.0);
        }
    }
    ASSERT_TRUE(by.count("reference"));
    by.erase("reference");
    const nlohmann::json limited = by.begin()->second;
    const nlohmann::json unlimited =
        resp["profiles"][0]["profile"] == "reference" ? resp["profiles"][0] : resp["profiles"][1];
    // The profile's [update] table is its budget; the reference has none (0: no limit).
    EXPECT_EQ(limited["rays_per_frame_budget"], 1);
    EXPECT_EQ(limited["upload_bytes_per_frame_budget"], kBudgetBytes);
    EXPECT_EQ(unlimited["rays_per_frame_budget"], 0);
    EXPECT_EQ(limited["probe_updates_per_frame_budget"], 1); // 1 ray buys at least one update
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& s = limited["schedules"][k];
        EXPECT_LE(s["probe_updates_per_frame"].get<double>(), 1.0);
        EXPECT_LE(s["upload_bytes_per_frame"].get<double>(), double(kBudgetBytes));
        EXPECT_LE(s["rays_per_frame"].get<double>(), raysPerUpdate);
        // A sun change marks every probe: unlimited, more are updated per frame.
        EXPECT_GT(unlimited["schedules"][k]["rays_per_frame"].get<double>(),
                  s["rays_per_frame"].get<double>());
    }
    // The readable outputs show the response column beside the frame time.
    EXPECT_NE(r.output.find("response t95 (frames)"), std::string::npos) << r.output;
    const std::string html = benchRespondReadText(dir / "report.html");
    EXPECT_NE(html.find("id=\"response\""), std::string::npos);
    EXPECT_NE(html.find("response t95 (frames)"), std::string::npos);
}

TEST(BenchRespondCli, WithoutRespondTheJsonHasNoResponse) {
    const fs::path dir = outputDir();
    auto args = benchRespondTinyBench(dir, "sun:off@2");
    const auto at = std::find(args.begin(), args.end(), "--respond");
    args.erase(at, at + 4); // --respond EVENT --respond-frames N
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(benchRespondReadText(dir / "out.json"));
    EXPECT_FALSE(j.contains("response"));
    EXPECT_EQ(r.output.find("response t95"), std::string::npos);
    EXPECT_EQ(benchRespondReadText(dir / "report.html").find("id=\"response\""), std::string::npos);
}

TEST(BenchRespondCli, ABadEventIsAOneLineErrorBeforeAnythingIsTimed) {
    const fs::path dir = outputDir();
    for (const std::string event : {"light:nolamp:off@1", "sun:off@99", "moon:off@1"}) {
        auto r = runProbebench(benchRespondTinyBench(dir, event));
        EXPECT_EQ(r.exitCode, 1) << event;
        EXPECT_EQ(r.output.rfind("probebench: error: --respond: ", 0), 0u) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(fs::exists(dir / "out.json"));
        EXPECT_FALSE(fs::exists(dir / "report.html"));
    }
    // Bench's own bake stores sparse probes, which respond cannot update: said before baking.
    auto args = benchRespondTinyBench(dir, "sun:off@2");
    const auto at = std::find(args.begin(), args.end(), "--probes");
    args.erase(at, at + 2);
    auto r = runProbebench(args);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.output, "probebench: error: --respond: needs --probes FILE, a dense probe file "
                        "(bake --dense)\n");
    EXPECT_FALSE(fs::exists(dir / "cache")) << "nothing baked";
}
