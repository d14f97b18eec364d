// `probebench render --path NAME|FILE --frames N --out-dir DIR [--compare-to full]`: numbered
// frames, the per-frame error files, cuts from a path file resetting the GI history, and clean
// one-line errors that leave nothing behind.
#include "image/Image.h"
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// A coarse bake of `rooms`, shared by the tests of this file (its own file name: the
// other CLI suites bake theirs in parallel).
const fs::path& renderPathRoomsProbes() {
    static const fs::path file =
        bakeCoarseRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_path_cli.pbp");
    return file;
}

std::vector<std::string> pathArgs(const std::string& path, const fs::path& outDir, int frames) {
    return {"render",
            "--scene",
            "rooms",
            "--view",
            "sunlit_room",
            "--width",
            "64",
            "--height",
            "36",
            "--path",
            path,
            "--frames",
            std::to_string(frames),
            "--out-dir",
            outDir.string()};
}

int countFiles(const fs::path& dir) {
    int n = 0;
    if (fs::is_directory(dir))
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
            ++n;
    return n;
}

} // namespace

TEST(RenderPathCli, WritesNumberedFrames) {
    const fs::path out = outputDir() / "frames";
    auto r = runProbebench(pathArgs("slow_pan", out, 3));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"frame_0000.png", "frame_0001.png", "frame_0002.png"}) {
        ASSERT_TRUE(fs::exists(out / f)) << f;
        EXPECT_EQ(pb::image::readPng((out / f).string()).width, 64);
    }
    EXPECT_EQ(countFiles(out), 3) << "frames only: no staging folder, no error files";
    EXPECT_NE(r.output.find("frame 3/3"), std::string::npos) << "progress: " << r.output;
}

TEST(RenderPathCli, ComparesEveryFrameWithFullResolution) {
    const fs::path out = outputDir() / "cmp";
    auto args = pathArgs("static", out, 5);
    args.insert(args.end(),
                {"--probes", renderPathRoomsProbes().string(), "--set", "gi.resolution=half",
                 "--set", "gi.upsample=temporal", "--compare-to", "full"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(out / "errors.csv");
    std::string line;
    int lines = 0;
    while (std::getline(csv, line))
        ++lines;
    EXPECT_EQ(lines, 6) << "header + one row per frame";
    std::ifstream jf(out / "errors.json");
    const nlohmann::json j = nlohmann::json::parse(jf);
    ASSERT_EQ(j["frames"].size(), 5u);
    EXPECT_EQ(j["profile"]["gi.upsample"], "temporal");
    EXPECT_TRUE(j["frames"][0]["cut"].get<bool>());
    EXPECT_FALSE(j["frames"][0]["history_used"].get<bool>());
    EXPECT_TRUE(j["frames"][1]["history_used"].get<bool>());
    // A still camera at half resolution: every pixel has been sampled by frame 3, after which
    // the frames equal full resolution (psnr null = identical).
    EXPECT_TRUE(j["frames"][4]["psnr_db"].is_null()) << j["frames"][4].dump();
    // One value for identical images everywhere (issue 25, item 9): inf / null, as `compare`
    // and `bench` write it - the summary no longer counts them as 100 dB.
    const auto& summary = j["summary"];
    EXPECT_FALSE(summary.contains("identical_frames_count_as_db")) << summary.dump();
    ASSERT_TRUE(summary.contains("identical_frames")) << summary.dump();
    int identical = 0;
    double differingSum = 0;
    for (const auto& f : j["frames"]) {
        if (f["psnr_db"].is_null())
            ++identical;
        else
            differingSum += f["psnr_db"].get<double>();
    }
    EXPECT_EQ(summary["identical_frames"].get<int>(), identical);
    if (identical < 5) {
        EXPECT_NEAR(summary["psnr_mean_db"].get<double>(), differingSum / (5 - identical), 1e-9);
    }
    EXPECT_EQ(r.output.find("identical = 100"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("identical (PSNR inf)"), std::string::npos) << r.output;
    const auto& conv = j["summary"]["convergence"];
    ASSERT_EQ(conv.size(), 1u);
    EXPECT_LE(conv[0]["frames_to_converge"].get<int>(), 3);
    EXPECT_EQ(j["frames"][2]["disoccluded_pixels"].get<int>(), 0) << "nothing moves";
}

TEST(RenderPathCli, PathFileCutsResetTheHistory) {
    const fs::path dir = outputDir();
    const fs::path file = dir / "cut.toml";
    std::ofstream(file) << "fps = 10\n"
                           "[[key]]\ntime = 0\nposition = [-0.6, 1.6, -2.2]\n"
                           "target = [-2.8, 0.9, 2.5]\nfov = 70\n"
                           "[[key]]\ntime = 0.3\nposition = [3.0, 1.6, 0.0]\n"
                           "target = [-1.7, 0.0, 0.5]\ncut = true\n";
    auto args = pathArgs(file.string(), dir / "out", 6);
    args.insert(args.end(),
                {"--probes", renderPathRoomsProbes().string(), "--set", "gi.resolution=half",
                 "--set", "gi.upsample=temporal", "--compare-to", "full"});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream jf(dir / "out" / "errors.json");
    const nlohmann::json j = nlohmann::json::parse(jf);
    ASSERT_EQ(j["frames"].size(), 6u);
    EXPECT_EQ(j["path"], "cut");
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(j["frames"][i]["cut"].get<bool>(), i == 0 || i == 3) << i;
        EXPECT_EQ(j["frames"][i]["history_used"].get<bool>(), i != 0 && i != 3) << i;
    }
    EXPECT_EQ(j["summary"]["convergence"].size(), 2u);
}

TEST(RenderPathCli, BadOptionsAreOneLineErrorsAndWriteNothing) {
    const fs::path dir = outputDir();
    const fs::path badFile = dir / "bad.toml";
    std::ofstream(badFile) << "[[key]]\ntime = 0\nposition = [0, 1, 0]\n";
    struct Case {
        std::vector<std::string> args;
        std::string mustName;
    };
    const fs::path out = dir / "out";
    auto path = [&](const std::string& p, std::vector<std::string> extra = {}) {
        auto a = pathArgs(p, out, 2);
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    };
    const std::vector<Case> cases = {
        {path("spiral"), "--path 'spiral': not a built-in path (static, slow_pan"},
        {path(badFile.string()), "bad.toml:1: [[key]] #1: missing key 'target'"},
        {path("static", {"--compare-to", "full"}), "--compare-to full: needs --probes"},
        {path("static", {"--probes", renderPathRoomsProbes().string(), "--compare-to", "half"}),
         "only 'full'"},
        {{"render", "--scene", "cornell", "--path", "doorway_walk", "--out-dir", out.string()},
         "needs the built-in 'rooms' scene"},
        {{"render", "--scene", "rooms", "--path", "static"}, "--out-dir DIR (required"},
        {{"render", "--scene", "rooms", "--out", (dir / "x.png").string(), "--compare-to", "full"},
         "--compare-to: needs --path"},
    };
    for (const Case& c : cases) {
        auto r = runProbebench(c.args);
        EXPECT_FALSE(r.crashed) << r.output;
        EXPECT_NE(r.exitCode, 0) << c.mustName;
        EXPECT_NE(r.output.find("probebench: error: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.mustName), std::string::npos) << r.output;
        EXPECT_EQ(countFiles(out), 0) << c.mustName << ": nothing may be left in the out dir";
        EXPECT_FALSE(fs::exists(dir / "x.png"));
    }
}
