// `probebench render` as a user runs it: images written, errors reported, never a crash.
#include "image/Image.h"
#include "support/ImageCompare.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"
#include "support/TinyGltf.h"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

double meanLuma(const pb::image::Image8& img) {
    double sum = 0;
    for (size_t i = 0; i < img.pixels.size(); i += 4)
        sum += 0.2126 * img.pixels[i] + 0.7152 * img.pixels[i + 1] + 0.0722 * img.pixels[i + 2];
    return sum / double(img.width * img.height);
}

// A failed command must say what went wrong in one line naming `mustName`, exit non-zero,
// not crash, and leave no output file behind.
void expectCleanFailure(const CommandResult& r, const std::string& mustName, const fs::path& out) {
    EXPECT_FALSE(r.crashed) << r.output;
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(mustName), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << "partial output written: " << out;
}

} // namespace

TEST(RenderCli, BuiltinSceneWritesPngOfRequestedSize) {
    fs::path dir = outputDir();
    auto r =
        runProbebench({"render", "--scene", "courtyard", "--width", "160", "--height", "90",
                       "--out", (dir / "c.png").string(), "--out-hdr", (dir / "c.pfm").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The scene is reported: its triangle count and bounds.
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(scene courtyard: [1-9][0-9]* triangles, )"
                                                       R"([0-9]+ instances, bounds \(.*\)\.\.\()")))
        << r.output;
    auto img = pb::image::readPng((dir / "c.png").string());
    EXPECT_EQ(img.width, 160);
    EXPECT_EQ(img.height, 90);
    EXPECT_GT(meanLuma(img), 10.0) << "image is black";
    auto hdr = pb::image::readPfm((dir / "c.pfm").string());
    ASSERT_EQ(hdr.width, 160);
    for (float v : hdr.pixels)
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
}

TEST(RenderCli, DumpGBufferWritesEveryChannel) {
    fs::path dir = outputDir();
    auto r =
        runProbebench({"render", "--scene", "rooms", "--width", "64", "--height", "36", "--out",
                       (dir / "r.png").string(), "--dump-gbuffer", (dir / "gb").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"albedo.png", "normal.png", "emissive.pfm", "flags.png", "depth.pfm"})
        EXPECT_TRUE(fs::exists(dir / "gb" / f)) << f;
}

TEST(RenderCli, UnknownViewListsTheViews) {
    fs::path dir = outputDir();
    auto r = runProbebench(
        {"render", "--scene", "cornell", "--view", "nope", "--out", (dir / "x.png").string()});
    expectCleanFailure(r, "nope", dir / "x.png");
    EXPECT_NE(r.output.find("default"), std::string::npos) << r.output;
}

TEST(RenderCli, MissingSceneFile) {
    fs::path dir = outputDir();
    auto r = runProbebench(
        {"render", "--scene", (dir / "missing.gltf").string(), "--out", (dir / "x.png").string()});
    expectCleanFailure(r, "missing.gltf", dir / "x.png");
}

TEST(RenderCli, MalformedGltfJson) {
    fs::path dir = outputDir();
    std::ofstream(dir / "bad.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ ";
    auto r = runProbebench(
        {"render", "--scene", (dir / "bad.gltf").string(), "--out", (dir / "x.png").string()});
    expectCleanFailure(r, "bad.gltf", dir / "x.png");
}

TEST(RenderCli, BinShorterThanDeclared) {
    fs::path dir = outputDir();
    auto gltf = writeTinyGltf(dir, "short", {.declaredBinBytes = 60, .truncateBinTo = 30});
    auto r = runProbebench({"render", "--scene", gltf.string(), "--out", (dir / "x.png").string()});
    expectCleanFailure(r, "short", dir / "x.png");
}

TEST(RenderCli, IndexOutOfRange) {
    fs::path dir = outputDir();
    auto gltf = writeTinyGltf(dir, "badindex", {.badIndex = 4000});
    auto r = runProbebench({"render", "--scene", gltf.string(), "--out", (dir / "x.png").string()});
    expectCleanFailure(r, "badindex", dir / "x.png");
    EXPECT_NE(r.output.find("range"), std::string::npos) << r.output;
}

TEST(RenderCli, ValidTinyGltfRenders) { // the control case for the broken ones above
    fs::path dir = outputDir();
    auto gltf = writeTinyGltf(dir, "ok");
    auto r = runProbebench({"render", "--scene", gltf.string(), "--width", "32", "--height", "32",
                            "--out", (dir / "x.png").string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "x.png"));
}

// egl and osmesa must agree within 1/255 per channel (both are llvmpipe here, through
// different context paths: ES 3.2 vs desktop 4.5 core compiling the same ES shaders).
class PlatformParity : public ::testing::TestWithParam<std::string> {};

TEST_P(PlatformParity, EglMatchesOsmesa) {
    fs::path dir = outputDir();
    std::vector<std::string> common{"render", "--scene",  GetParam(), "--width",
                                    "240",    "--height", "135"};
    auto egl = common, osm = common;
    egl.insert(egl.end(), {"--platform", "egl", "--out", (dir / "egl.png").string()});
    osm.insert(osm.end(), {"--platform", "osmesa", "--out", (dir / "osmesa.png").string()});
    auto r1 = runProbebench(egl);
    auto r2 = runProbebench(osm);
    ASSERT_EQ(r1.exitCode, 0) << r1.output;
    ASSERT_EQ(r2.exitCode, 0) << r2.output;
    auto a = pb::image::readPng((dir / "egl.png").string());
    auto b = pb::image::readPng((dir / "osmesa.png").string());
    ImageTolerance tol{1, 0.0, 1.0};
    ImageDiff d = compareImages(a, b, tol);
    if (!withinTolerance(d, tol)) writeFailureImages(dir, a, b);
    EXPECT_TRUE(withinTolerance(d, tol)) << d.describe();
}

// The window backend renders the same frame (under Xvfb here: GLX on llvmpipe, desktop GL 4.5).
TEST(RenderCli, GlfwWindowMatchesEgl) {
    if (runCommand({"sh", "-c", "command -v xvfb-run"}).exitCode != 0) {
        if (underCi()) FAIL() << "xvfb-run missing under CI (test.sh installs xvfb)";
        GTEST_SKIP() << "xvfb-run not installed";
    }
    fs::path dir = outputDir();
    std::vector<std::string> args{"render",   "--scene", "courtyard", "--width", "240",
                                  "--height", "135",     "--frames",  "2"};
    auto egl = args;
    egl.insert(egl.end(), {"--platform", "egl", "--out", (dir / "egl.png").string()});
    std::vector<std::string> glfw{"xvfb-run", "-a", binaryPath().string()};
    glfw.insert(glfw.end(), args.begin(), args.end());
    glfw.insert(glfw.end(), {"--platform", "glfw", "--out", (dir / "glfw.png").string()});
    auto r1 = runProbebench(egl);
    auto r2 = runCommand(glfw);
    ASSERT_EQ(r1.exitCode, 0) << r1.output;
    ASSERT_EQ(r2.exitCode, 0) << r2.output;
    auto a = pb::image::readPng((dir / "egl.png").string());
    auto b = pb::image::readPng((dir / "glfw.png").string());
    ImageTolerance tol{1, 0.0, 1.0};
    ImageDiff d = compareImages(a, b, tol);
    if (!withinTolerance(d, tol)) writeFailureImages(dir, a, b);
    EXPECT_TRUE(withinTolerance(d, tol)) << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Builtin, PlatformParity,
                         ::testing::Values("cornell", "rooms", "courtyard"));

// Every shared scene renders: exit 0, a lit (not black, not blank) image.
class SharedSceneRender : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedSceneRender, RendersLitImage) {
    PB_REQUIRE_SHARED_SCENES();
    fs::path dir = outputDir();
    auto r = runProbebench({"render", "--scene", (scenesDir() / GetParam()).string(), "--width",
                            "320", "--height", "180", "--out", (dir / "s.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto img = pb::image::readPng((dir / "s.png").string());
    double luma = meanLuma(img);
    EXPECT_GT(luma, 8.0) << "too dark";
    EXPECT_LT(luma, 250.0) << "blown out";
}

INSTANTIATE_TEST_SUITE_P(Shared, SharedSceneRender,
                         ::testing::Values("cornell_box/CornellBox-Original.gltf",
                                           "sponza_decimated/sponza_s_lod4.glb",
                                           "space_ship_hallway/space_ship_hallway.glb",
                                           "japanese_bridge_garden/japanese_bridge_garden.gltf",
                                           "dream_apartment/dream_apartment.gltf"),
                         [](const auto& info) {
                             std::string n = info.param.substr(0, info.param.find('/'));
                             return n;
                         });

// Issue 42 item 1: the default view says what it sees. One that sees no geometry is warned
// about in one line with its pose as a ready --camera; a good one is not; a pose the user
// chose is not second-guessed. --json gives the pose and the check.
TEST(RenderCli, ADefaultViewThatSeesNothingIsWarnedWithItsCamera) {
    const fs::path dir = outputDir();
    auto empty = runProbebench({"render", "--scene", "empty", "--width", "32", "--height", "18",
                                "--out", (dir / "empty.png").string()});
    ASSERT_EQ(empty.exitCode, 0) << empty.output;
    EXPECT_NE(empty.output.find("warning: the default view of 'empty' sees 0% geometry from the front"),
              std::string::npos)
        << empty.output;
    EXPECT_NE(empty.output.find("; pass --camera or --view (it was --camera "), std::string::npos)
        << empty.output;

    auto cornell = runProbebench({"render", "--scene", "cornell", "--width", "32", "--height", "18",
                                  "--out", (dir / "cornell.png").string(), "--json",
                                  (dir / "cornell.json").string()});
    ASSERT_EQ(cornell.exitCode, 0) << cornell.output;
    EXPECT_EQ(cornell.output.find("warning:"), std::string::npos) << cornell.output;
    std::ifstream in(dir / "cornell.json");
    std::stringstream ss;
    ss << in.rdbuf();
    const auto j = nlohmann::json::parse(ss.str());
    EXPECT_TRUE(j["view_check"]["good"].get<bool>()) << j.dump();
    EXPECT_GE(j["view_check"]["front_fraction"].get<double>(), 0.5);
    // The pose, given back as --camera, renders the same picture.
    auto again = runProbebench({"render", "--scene", "cornell", "--width", "32", "--height", "18",
                                "--camera", j["camera"].get<std::string>(), "--out",
                                (dir / "again.png").string()});
    ASSERT_EQ(again.exitCode, 0) << again.output;
    const auto a = pb::image::readPng((dir / "cornell.png").string());
    const auto b = pb::image::readPng((dir / "again.png").string());
    EXPECT_EQ(a.pixels, b.pixels);

    // A camera the user chose that sees only sky: their choice, no warning.
    auto sky = runProbebench({"render", "--scene", "cornell", "--width", "32", "--height", "18",
                              "--camera", "0,1,50,0,1,100", "--out", (dir / "sky.png").string()});
    ASSERT_EQ(sky.exitCode, 0) << sky.output;
    EXPECT_EQ(sky.output.find("warning:"), std::string::npos) << sky.output;
}
