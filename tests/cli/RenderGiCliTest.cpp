// `probebench render --probes FILE [--scenario NAME] [--set key=value ...]`: DDGI from a
// baked file, profile switches from the command line, and clean one-line errors.
#include "image/Image.h"
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// A coarse bake of `rooms`, shared by the tests of this file (its own file name: the
// other CLI suites bake theirs in parallel).
const fs::path& renderGiRoomsProbes() {
    static const fs::path file = bakeCoarseRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_gi_cli.pbp");
    return file;
}

double renderGiMeanLuma(const pb::image::Image8& img) {
    double sum = 0;
    for (size_t i = 0; i < img.pixels.size(); i += 4)
        sum += 0.2126 * img.pixels[i] + 0.7152 * img.pixels[i + 1] + 0.0722 * img.pixels[i + 2];
    return sum / double(img.width * img.height);
}

std::vector<std::string> renderArgs(const fs::path& out) {
    return {"render", "--scene",  "rooms", "--view", "sunlit_room", "--width",
            "96",     "--height", "54",    "--out",  out.string()};
}

} // namespace

TEST(RenderGiCli, ProbesChangeTheIndirectLight) {
    fs::path dir = outputDir();
    auto plain = runProbebench(renderArgs(dir / "plain.png"));
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    auto args = renderArgs(dir / "gi.png");
    args.insert(args.end(), {"--probes", renderGiRoomsProbes().string(), "--scenario", "day"});
    auto gi = runProbebench(args);
    ASSERT_EQ(gi.exitCode, 0) << gi.output;
    EXPECT_NE(gi.output.find("gi: ddgi, 1 of 1 volume(s), scenario 'day'"), std::string::npos)
        << gi.output;
    auto a = pb::image::readPng((dir / "plain.png").string());
    auto b = pb::image::readPng((dir / "gi.png").string());
    EXPECT_GT(std::abs(renderGiMeanLuma(a) - renderGiMeanLuma(b)), 1.0)
        << "GI must replace the ambient";
    EXPECT_GT(renderGiMeanLuma(b), 5.0) << "a sunlit room with GI is not black";
}

TEST(RenderGiCli, SwitchesFromTheCommandLine) {
    fs::path dir = outputDir();
    auto args = renderArgs(dir / "half.png");
    args.insert(args.end(),
                {"--probes", renderGiRoomsProbes().string(), "--set", "gi.resolution=half", "--set",
                 "gi.target_format=r11g11b10f", "--set", "gi.loops=split"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gi.resolution=half"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gi.loops=split"), std::string::npos) << r.output;
}

TEST(RenderGiCli, BadSwitchesAreOneLineErrors) {
    fs::path dir = outputDir();
    struct Case {
        std::vector<std::string> extra;
        std::string mustName;
    };
    const std::vector<Case> cases = {
        {{"--set", "gi.resolution=eighth"}, "full, half, quarter"},
        {{"--set", "gi.resolutoin=half"}, "unknown switch 'gi.resolutoin'"},
        {{"--set", "gi.loops"}, "expected key=value"},
        {{"--scenario", "dusk"}, "'dusk' is not in"},
        {{"--set", "gi.volume_lod=omit:nope"}, "no volume named 'nope'"},
        {{"--debug", "nope"},
         "unknown debug view (views: gi_only, probes_irradiance, probes_visibility, "
         "volume_coverage)"},
        {{"--debug", "volume_coverage", "--out-hdr", "x.pfm"}, "8-bit image only"},
    };
    for (const Case& c : cases) {
        fs::path out = dir / "bad.png";
        auto args = renderArgs(out);
        args.insert(args.end(), {"--probes", renderGiRoomsProbes().string()});
        args.insert(args.end(), c.extra.begin(), c.extra.end());
        auto r = runProbebench(args);
        EXPECT_FALSE(r.crashed) << r.output;
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(c.mustName), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.mustName;
    }
    auto missing = renderArgs(dir / "missing.png");
    missing.insert(missing.end(), {"--probes", (dir / "no_such.pbp").string()});
    auto r = runProbebench(missing);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("no_such.pbp"), std::string::npos) << r.output;
    auto noProbes = renderArgs(dir / "np.png");
    noProbes.insert(noProbes.end(), {"--set", "gi.loops=split"});
    r = runProbebench(noProbes);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--probes"), std::string::npos) << r.output;
}

TEST(RenderGiCli, ListSwitchesDescribesEverySwitch) {
    auto r = runProbebench({"render", "--list-switches", "--set", "gi.loops=split"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* key :
         {"gi.technique", "gi.resolution", "gi.target_format", "gi.precision", "gi.loops",
          "gi.probe_order", "gi.multi_volume", "gi.dynamic", "gi.volume_lod"})
        EXPECT_NE(r.output.find(key), std::string::npos) << key;
    EXPECT_NE(r.output.find("gi.loops = split  (default fused)"), std::string::npos) << r.output;
}

// Every value of every switch renders (fp16, stencil, SH for a dynamic node included).
TEST(RenderGiCli, EverySwitchValueRenders) {
    fs::path dir = outputDir();
    const std::vector<std::vector<std::string>> sets = {
        {"gi.precision=fp16"},
        {"gi.multi_volume=stencil", "gi.resolution=quarter"},
        {"gi.dynamic=sh"},
    };
    for (const auto& set : sets) {
        auto args = renderArgs(dir / "switch.png");
        args.insert(args.end(), {"--probes", renderGiRoomsProbes().string(), "--dynamic", "table"});
        for (const auto& kv : set)
            args.insert(args.end(), {"--set", kv});
        auto r = runProbebench(args);
        EXPECT_EQ(r.exitCode, 0) << set.front() << ": " << r.output;
        EXPECT_NE(r.output.find(set.front()), std::string::npos) << r.output;
    }
}

TEST(RenderGiCli, DebugViewsWriteTheirImages) {
    fs::path dir = outputDir();
    auto normalArgs = renderArgs(dir / "normal.png");
    normalArgs.insert(normalArgs.end(), {"--probes", renderGiRoomsProbes().string()});
    ASSERT_EQ(runProbebench(normalArgs).exitCode, 0);
    const auto normal = pb::image::readPng((dir / "normal.png").string());
    for (const char* view :
         {"gi_only", "probes_irradiance", "probes_visibility", "volume_coverage"}) {
        const fs::path out = dir / (std::string(view) + ".png");
        auto args = renderArgs(out);
        args.insert(args.end(), {"--probes", renderGiRoomsProbes().string(), "--debug", view});
        auto r = runProbebench(args);
        ASSERT_EQ(r.exitCode, 0) << view << ": " << r.output;
        EXPECT_NE(r.output.find(std::string("debug view ") + view), std::string::npos) << r.output;
        const auto img = pb::image::readPng(out.string());
        EXPECT_EQ(img.height, normal.height);
        // volume_coverage: shading volume | evaluations per pixel, side by side.
        EXPECT_EQ(img.width,
                  std::string(view) == "volume_coverage" ? 2 * normal.width : normal.width);
        if (img.width == normal.width) {
            EXPECT_GT(std::abs(renderGiMeanLuma(img) - renderGiMeanLuma(normal)), 0.5) << view;
        }
    }
    auto noProbes = renderArgs(dir / "np.png");
    noProbes.insert(noProbes.end(), {"--debug", "gi_only"});
    auto r = runProbebench(noProbes);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("need --probes"), std::string::npos) << r.output;
}

// --json: the frame's report on stdout, with pixels evaluated per volume.
TEST(RenderGiCli, JsonReportsPixelsEvaluatedPerVolume) {
    fs::path dir = outputDir();
    for (const char* mode : {"naive", "stencil"}) {
        auto args = renderArgs(dir / "json.png");
        args.insert(args.end(), {"--probes", renderGiRoomsProbes().string(), "--json", "--set",
                                 std::string("gi.multi_volume=") + mode});
        auto r = runProbebench(args);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        // Human lines (stderr) come first; the JSON document is printed last.
        const size_t start = r.output.find("\n{");
        ASSERT_NE(start, std::string::npos) << r.output;
        const nlohmann::json j = nlohmann::json::parse(r.output.substr(start + 1));
        const nlohmann::json& pass = j.at("gi").at("pass");
        EXPECT_EQ(pass.at("multi_volume"), mode);
        ASSERT_FALSE(pass.at("volumes").empty());
        long long sum = 0;
        for (const auto& v : pass.at("volumes"))
            sum += v.at("evaluated_pixels").get<long long>();
        EXPECT_EQ(sum, pass.at("evaluations").get<long long>());
        EXPECT_GT(pass.at("covered_pixels").get<long long>(), 96 * 54 / 2);
        EXPECT_EQ(pass.at("target").at("width"), 96);
    }
}
