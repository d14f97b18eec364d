// `probebench costmodel`: JSON with every counter and cache field, the readable table, and
// one-line errors for bad input.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& roomsProbes() {
    static const fs::path file = [] {
        fs::path f = fs::path(PB_TEST_OUTPUT_DIR) / "rooms_costmodel_cli.pbp";
        auto r = runProbebench(
            {"bake", "--scene", "rooms", "--rays", "16", "--bounces", "1", "--out", f.string()});
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return f;
    }();
    return file;
}

std::vector<std::string> base() {
    return {"costmodel", "--scene", "rooms",    "--probes", roomsProbes().string(),
            "--width",   "64",      "--height", "36"};
}

void costModelExpectOneLineError(const std::vector<std::string>& extra, const std::string& needle) {
    std::vector<std::string> args = base();
    args.insert(args.end(), extra.begin(), extra.end());
    auto r = runProbebench(args);
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_FALSE(r.crashed);
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

} // namespace

TEST(CostModelCli, JsonHasEveryFieldForEveryVariantAndCache) {
    std::vector<std::string> args = base();
    args.insert(args.end(), {"--cache", "handheld", "--cache-size", "65536", "--line", "128",
                             "--ways", "8", "--set", "gi.loops=split", "--json"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    for (const char* k : {"scene", "view", "camera", "probe_format", "memory_layout", "profile",
                          "profile_variant", "shading_order", "gi_apply", "caches", "cache_model"})
        EXPECT_TRUE(j.contains(k)) << k;
    EXPECT_EQ(j["profile_variant"], "xyz/split");
    const auto& p = j["gi_apply"];
    for (const char* k :
         {"gbuffer_width", "target_width", "target_pixels", "gi_pixels", "draw_calls", "clears",
          "program_binds", "texture_binds", "texture_unbinds", "gbuffer_fetches", "probe_fetches",
          "fetches_per_gi_pixel", "max_fetches_per_lookup", "probe_footprint_bytes",
          "render_target_bytes_written", "clear_bytes", "gpu_probe_bytes", "volumes"})
        EXPECT_TRUE(p.contains(k)) << k;
    ASSERT_FALSE(p["volumes"].empty());
    for (const char* k : {"name", "fragments", "evaluated", "won", "sky_skipped", "outside_skipped",
                          "faded_out", "fetches", "probe_footprint_bytes"})
        EXPECT_TRUE(p["volumes"][0].contains(k)) << k;
    ASSERT_EQ(j["caches"].size(), 2u);
    EXPECT_EQ(j["caches"][1]["name"], "custom");
    ASSERT_EQ(j["cache_model"].size(), 8u); // 4 variants x 2 caches
    for (const auto& res : j["cache_model"]) {
        for (const char* k :
             {"variant", "cache", "probe_line_accesses", "probe_line_hits", "probe_hit_rate",
              "probe_bytes_missed_per_pixel", "all_bytes_missed_per_pixel"})
            EXPECT_TRUE(res.contains(k)) << k;
        EXPECT_GE(res["probe_hit_rate"].get<double>(), 0.0);
        EXPECT_LE(res["probe_hit_rate"].get<double>(), 1.0);
    }
}

TEST(CostModelCli, PrintsATableOfVariantsAndCaches) {
    std::vector<std::string> args = base();
    args.insert(args.end(), {"--cache", "pc-high", "--layout", "linear"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* s : {"xyz/fused *", "slice_first/split", "pc-high", "hit rate", "B missed/px",
                          "draws", "memory layout linear", "--camera"})
        EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
}

TEST(CostModelCli, BadInputIsAOneLineError) {
    costModelExpectOneLineError({"--cache", "switch"}, "unknown cache preset 'switch'");
    costModelExpectOneLineError({"--cache-size", "65536"}, "--cache-size, --line and --ways");
    costModelExpectOneLineError({"--cache-size", "65536", "--line", "48", "--ways", "4"},
                                "line size");
    costModelExpectOneLineError({"--layout", "swizzled"}, "--layout");
    costModelExpectOneLineError({"--set", "gi.loops=twisted"}, "gi.loops");
    costModelExpectOneLineError({"--view", "nowhere"}, "nowhere");
    costModelExpectOneLineError({"--worst-case", "--view", "doorway"}, "--worst-case");
    costModelExpectOneLineError({"--warp", "0"}, "--warp");
    auto missing = runProbebench({"costmodel", "--scene", "rooms", "--probes", "/nonexistent.pbp"});
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_FALSE(missing.crashed);
    EXPECT_EQ(std::count(missing.output.begin(), missing.output.end(), '\n'), 1) << missing.output;
}
