// `probebench profiles`, `--profile` on the rendering commands, and `probebench bench` as a user
// runs them: the JSON's shape on a tiny run (small size, 2 rounds), one-line errors that leave
// no output file, and the HTML report opening in headless Chromium without console errors.
#include "image/Image.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

std::string benchReadText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// handheld with the switch values every branch implements today (the merge adds fp16,
// stencil and SH; this test's runs must not depend on them).
fs::path todayProfile(const fs::path& dir) {
    fs::path p = dir / "handheld-today.toml";
    std::ofstream(p) << "inherit = \"handheld\"\ndescription = \"handheld, implemented values\"\n"
                        "[gi]\nprecision = \"fp32\"\nmulti_volume = \"naive\"\n"
                        "dynamic = \"per_pixel\"\n";
    return p;
}

// Probes baked once for every test of this file (the bake cache is keyed by input hash and
// written atomically, so parallel test processes share it safely).
std::string probeCache() {
    return (fs::path(PB_TEST_OUTPUT_DIR) / "bench-probe-cache").string();
}

std::vector<std::string> tinyBench(const fs::path& dir, const fs::path& profile) {
    return {"bench",
            "--scene",
            "cornell",
            "--profiles",
            "reference," + profile.string(),
            "--ablate",
            "--width",
            "64",
            "--height",
            "36",
            "--rounds",
            "2",
            "--frames",
            "1",
            "--warmup",
            "1",
            "--cache-dir",
            probeCache(),
            "--json",
            (dir / "out.json").string(),
            "--html",
            (dir / "report.html").string()};
}

bool firstLineIsTheError(const CommandResult& r, const std::string& text) {
    return r.output.rfind("probebench: error: " + text, 0) == 0 &&
           std::count(r.output.begin(), r.output.end(), '\n') == 1;
}

} // namespace

TEST(ProfilesCli, ListsEveryProfileWithASummary) {
    auto r = runProbebench({"profiles"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* n : {"reference", "pc-high", "console-base", "handheld", "pc-low"})
        EXPECT_NE(r.output.find(std::string("\n") + n + " "), std::string::npos) << n << r.output;
    auto j = runProbebench({"profiles", "--json"});
    ASSERT_EQ(j.exitCode, 0) << j.output;
    auto list = nlohmann::json::parse(j.output);
    ASSERT_GE(list.size(), 5u);
    for (const auto& p : list) {
        EXPECT_TRUE(p.contains("summary")) << p.dump();
        EXPECT_TRUE(p["switches"].contains("gi.resolution"));
        EXPECT_GT(p["output"]["width"].get<int>(), 0);
    }
}

TEST(ProfilesCli, ShowWritesAProfileThatLoadsBackTheSame) {
    fs::path dir = outputDir();
    auto shown = runProbebench({"profiles", "--show", "handheld"});
    ASSERT_EQ(shown.exitCode, 0) << shown.output;
    EXPECT_NE(shown.output.find("precision = \"fp16\""), std::string::npos) << shown.output;
    std::ofstream(dir / "copy.toml") << shown.output;
    auto again = runProbebench({"profiles", "--show", (dir / "copy.toml").string()});
    ASSERT_EQ(again.exitCode, 0) << again.output;
    // Everything after the header comment (which names the inheritance) is identical.
    EXPECT_EQ(again.output.substr(again.output.find('\n')),
              shown.output.substr(shown.output.find('\n')));
}

TEST(ProfilesCli, ABadProfileIsAOneLineErrorNamingFileLineAndKey) {
    fs::path dir = outputDir();
    fs::path bad = dir / "bad.toml";
    std::ofstream(bad) << "inherit = \"reference\"\n[gi]\nresolution = \"eighth\"\n";
    auto r = runProbebench({"profiles", "--show", bad.string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(firstLineIsTheError(r, bad.string() + ":3: key 'gi.resolution': 'eighth' is not "
                                                      "allowed"))
        << r.output;
    auto render = runProbebench({"render", "--scene", "cornell", "--profile", bad.string(), "--out",
                                 (dir / "x.png").string()});
    EXPECT_EQ(render.exitCode, 1);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(ProfilesCli, RenderAndCostModelTakeTheProfilesSizeAndCache) {
    fs::path dir = outputDir();
    fs::path today = todayProfile(dir);
    auto noProbes = runProbebench({"render", "--scene", "cornell", "--profile", today.string(),
                                   "--out", (dir / "x.png").string()});
    EXPECT_EQ(noProbes.exitCode, 1);
    EXPECT_TRUE(firstLineIsTheError(noProbes, "--profile: the GI switches need --probes"))
        << noProbes.output;
    fs::path probes = dir / "cornell.pbp";
    auto bake =
        runProbebench({"bake", "--scene", "cornell", "--volumes", "auto-uniform", "--spacing",
                       "0.5", "--rays", "16", "--bounces", "1", "--out", probes.string()});
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    auto r = runProbebench({"render", "--scene", "cornell", "--probes", probes.string(),
                            "--profile", today.string(), "--out", (dir / "p.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("profile handheld-today, switches: gi.resolution=half"),
              std::string::npos)
        << r.output;
    auto img = pb::image::readPng((dir / "p.png").string());
    EXPECT_EQ(img.width, 1280); // handheld's output size
    EXPECT_EQ(img.height, 720);
    auto sized = runProbebench({"render", "--scene", "cornell", "--probes", probes.string(),
                                "--profile", today.string(), "--width", "64", "--height", "36",
                                "--out", (dir / "s.png").string()});
    ASSERT_EQ(sized.exitCode, 0) << sized.output;
    EXPECT_EQ(pb::image::readPng((dir / "s.png").string()).width, 64);

    auto cost =
        runProbebench({"costmodel", "--scene", "cornell", "--probes", probes.string(), "--profile",
                       today.string(), "--width", "64", "--height", "36", "--json"});
    ASSERT_EQ(cost.exitCode, 0) << cost.output;
    auto j = nlohmann::json::parse(cost.output);
    std::set<std::string> caches;
    for (const auto& c : j["caches"])
        caches.insert(c["name"].get<std::string>());
    EXPECT_EQ(caches, std::set<std::string>{"handheld"}) << "the profile's cache preset";
}

TEST(BenchCli, TinyRunWritesTheJsonShapeTheReportAndHeatMaps) {
    fs::path dir = outputDir();
    auto r = runProbebench(tinyBench(dir, todayProfile(dir)));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("| handheld-today | 64x36 |"), std::string::npos) << r.output;
    auto j = nlohmann::json::parse(benchReadText(dir / "out.json"));
    EXPECT_EQ(j["schema"], "probebench.bench/1");
    for (const char* k : {"platform", "gl_version", "gl_renderer", "driver", "cpu",
                          "lp_num_threads", "commit", "date", "load_average_start"})
        EXPECT_TRUE(j["context"].contains(k)) << k;
    // Timed in a non-debug context (KHR_debug's checks are not the device's cost), and said so
    // (issue 25, item 3); EGL on Mesa gives ES 3.2, where the context can tell.
    EXPECT_EQ(j["context"]["debug_context"], false) << j["context"].dump();
    EXPECT_EQ(j["context"]["platform"].get<std::string>().find("debug context"), std::string::npos);
    EXPECT_NE(r.output.find("a non-debug context"), std::string::npos) << r.output;
    // 2 rounds give no 95% interval: said before measuring and in the summary (item 1).
    EXPECT_NE(r.output.find("warning: 2 round(s) give delta intervals of 50% at most"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(j["settings"]["rounds"], 2);
    EXPECT_FALSE(j["settings"]["timing_method"].get<std::string>().empty());
    EXPECT_EQ(j["view"]["source"], "worst-case");
    ASSERT_EQ(j["profiles"].size(), 2u);
    const auto& hh = j["profiles"][1];
    EXPECT_EQ(hh["name"], "handheld-today");
    EXPECT_EQ(hh["status"], "ok");
    EXPECT_DOUBLE_EQ(hh["coverage"]["fraction"].get<double>(), 1.0) << "the worst-case view";
    EXPECT_TRUE(hh["vs_reference"]["measured"].get<bool>());
    EXPECT_TRUE(hh["vs_reference"]["delta_ms"].contains("ci_low"));
    EXPECT_GT(hh["accuracy"]["relative_mse_gi"].get<double>(), 0.0) << "half res is not exact";
    EXPECT_TRUE(fs::exists(hh["accuracy"]["heatmap"].get<std::string>()));
    // The two frames FLIP compared, written beside the heat map (issue 25, item 10).
    for (const char* frame : {"frame", "reference_frame"}) {
        ASSERT_TRUE(hh["accuracy"][frame].is_string()) << frame << hh["accuracy"].dump();
        const auto png = pb::image::readPng(hh["accuracy"][frame].get<std::string>());
        EXPECT_EQ(png.width, 64) << frame;
    }
    // Ablation: every switch where handheld-today differs from reference, both ways.
    std::set<std::string> ablated;
    for (const auto& a : hh["ablation"]) {
        ablated.insert(a["switch"].get<std::string>());
        EXPECT_TRUE(a["in_profile"]["measured"].get<bool>()) << a.dump();
        EXPECT_TRUE(a["on_reference"]["measured"].get<bool>()) << a.dump();
    }
    std::set<std::string> differing; // from the profiles' own switches (new switches included)
    const auto& refSwitches = j["profiles"][0]["profile"]["switches"];
    for (auto it = refSwitches.begin(); it != refSwitches.end(); ++it)
        if (hh["profile"]["switches"][it.key()] != it.value()) differing.insert(it.key());
    EXPECT_EQ(ablated, differing);
    for (const char* key : {"gi.resolution", "gi.target_format", "gi.loops", "gi.probe_order"})
        EXPECT_TRUE(ablated.count(key)) << key;
    // Every variant records its passes (the frame's pass list), frames and coverage.
    std::map<std::string, nlohmann::json> switchesOf;
    for (const auto& v : j["variants"]) {
        ASSERT_EQ(v["status"], "ok") << v.dump();
        switchesOf[v["id"].get<std::string>()] = v["switches"];
        std::vector<std::string> passes;
        for (const auto& p : v["passes"])
            passes.push_back(p["name"]);
        EXPECT_NE(std::find(passes.begin(), passes.end(), "gi-apply"), passes.end());
        EXPECT_NE(std::find(passes.begin(), passes.end(), "gbuffer"), passes.end());
        EXPECT_EQ(v["frame_samples_ms"].size(), 2u); // rounds x frames, warm-up excluded
        EXPECT_TRUE(v.contains("coverage"));
    }
    // An ablation run changes exactly one switch against the run it is compared with.
    for (const auto& a : hh["ablation"])
        for (const char* side : {"in_profile", "on_reference"}) {
            const auto& off = switchesOf[a[side]["off"].get<std::string>()];
            const auto& on = switchesOf[a[side]["on"].get<std::string>()];
            int differ = 0;
            for (auto it = off.begin(); it != off.end(); ++it)
                differ += on[it.key()] != it.value();
            EXPECT_EQ(differ, 1) << a.dump();
        }
    EXPECT_TRUE(j["profiles"][0]["vs_reference"].is_null()) << "reference is the baseline";
    std::string html = benchReadText(dir / "report.html");
    EXPECT_NE(html.find("handheld-today"), std::string::npos);
    EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos) << "heat maps inline";
    // Beside each profile's heat map: the reference's frame and the profile's, inline.
    EXPECT_NE(html.find("<img alt=\"reference frame for handheld-today\" src=\"data:image/png;base64,"),
              std::string::npos);
    EXPECT_NE(html.find("<img alt=\"frame handheld-today\" src=\"data:image/png;base64,"),
              std::string::npos);
    EXPECT_LT(html.find("<img alt=\"frame handheld-today\""),
              html.find("<img alt=\"FLIP heat map handheld-today\""))
        << "the frames sit before their heat map";
}

TEST(BenchCli, ErrorsAreOneLineAndWriteNothing) {
    fs::path dir = outputDir();
    auto args = tinyBench(dir, "nope");
    auto r = runProbebench(args);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(firstLineIsTheError(r, "profile 'nope': no such profile")) << r.output;
    auto bad = tinyBench(dir, todayProfile(dir));
    bad.insert(bad.end(), {"--set", "gi.resolution=eighth"});
    r = runProbebench(bad);
    EXPECT_EQ(r.exitCode, 2) << "a value out of range is a usage error";
    EXPECT_TRUE(firstLineIsTheError(r, "--set gi.resolution=eighth: allowed values")) << r.output;
    auto zero = tinyBench(dir, todayProfile(dir));
    zero[11] = "0"; // --rounds 0
    r = runProbebench(zero);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(firstLineIsTheError(r, "--rounds must be")) << r.output;
    // An unknown timing method is refused before the view search and the bake (it was
    // found only after both).
    auto timing = tinyBench(dir, todayProfile(dir));
    timing.insert(timing.end(), {"--timing", "cpu-finish"});
    r = runProbebench(timing);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(firstLineIsTheError(r, "--timing: 'cpu-finish' is not one of auto, cpu"))
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    EXPECT_FALSE(fs::exists(dir / "report.html"));
}

// The report is one self-contained file: opened in headless Chromium it shows its tables
// and charts, logs nothing to the console, and loads nothing but data: URIs. Chromium is in
// scripts/deps.sh, so ./test.sh installs it; the test skips without it only outside CI (a
// developer's machine that has not run ./test.sh), and fails under CI=true.
TEST(BenchCli, ReportOpensInHeadlessChromiumWithoutErrors) {
    std::string chromium;
    for (const char* c : {"chromium", "chromium-browser"})
        if (runCommand({"sh", "-c", std::string("command -v ") + c}).exitCode == 0) chromium = c;
    if (chromium.empty()) {
        const char* ci = std::getenv("CI");
        if (ci && std::string(ci) == "true")
            FAIL() << "chromium is not installed under CI (scripts/deps.sh installs it)";
        GTEST_SKIP() << "chromium not installed (./test.sh or apt-get install chromium)";
    }
    fs::path dir = outputDir();
    auto r = runProbebench(tinyBench(dir, todayProfile(dir)));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto dom = runCommand({"sh", "-c",
                           "timeout 120 " + chromium +
                               " --headless=new --no-sandbox --disable-gpu --enable-logging=stderr "
                               "--v=0 --dump-dom 'file://" +
                               (dir / "report.html").string() + "' 2>&1"});
    ASSERT_EQ(dom.exitCode, 0) << dom.output;
    EXPECT_NE(dom.output.find("id=\"profiles\""), std::string::npos) << "the DOM was dumped";
    EXPECT_NE(dom.output.find("aria-label=\"Pareto chart\""), std::string::npos);
    EXPECT_EQ(dom.output.find(":CONSOLE"), std::string::npos) << dom.output;
    EXPECT_EQ(dom.output.find("Uncaught"), std::string::npos) << dom.output;
    std::smatch m;
    std::string rest = dom.output;
    while (std::regex_search(rest, m, std::regex("src=\"([^\"]*)\""))) {
        EXPECT_EQ(m[1].str().rfind("data:", 0), 0u) << "external resource " << m[1];
        rest = m.suffix();
    }
}
