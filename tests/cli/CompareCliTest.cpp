// `probebench compare` as a user runs it: metrics printed, JSON, heat map, one-line errors.
#include "image/Image.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

pb::image::Image8 grey(int w, int h, std::uint8_t v) {
    pb::image::Image8 img;
    img.width = w;
    img.height = h;
    img.pixels.assign(size_t(w) * h * 4, 255);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (i % 4 != 3) img.pixels[i] = v;
    return img;
}

nlohmann::json parse(const CommandResult& r) {
    // RunCommand merges stderr into the output; on success nothing is written there.
    return nlohmann::json::parse(r.output, nullptr, false);
}

void compareExpectOneLineError(const CommandResult& r, const std::string& mustName) {
    EXPECT_FALSE(r.crashed) << r.output;
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(mustName), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

} // namespace

TEST(CompareCli, IdenticalImagesInJson) {
    const fs::path dir = outputDir();
    pb::image::writePng((dir / "a.png").string(), grey(24, 16, 90));
    const auto r = runProbebench({"compare", "--test", (dir / "a.png").string(), "--reference",
                                  (dir / "a.png").string(), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = parse(r);
    ASSERT_FALSE(j.is_discarded()) << r.output;
    EXPECT_TRUE(j["identical"].get<bool>());
    EXPECT_TRUE(j["psnr_db"].is_null());
    EXPECT_NEAR(j["ssim"].get<double>(), 1.0, 1e-12);
    EXPECT_EQ(j["flip_mean"].get<double>(), 0.0);
    EXPECT_EQ(j["flip_max"].get<double>(), 0.0);
    EXPECT_EQ(j["width"], 24);
    EXPECT_EQ(j["ppd"].get<double>(), 67.0);
}

TEST(CompareCli, UniformOffsetTextAndHeatMap) {
    // Grey 100 vs 110: MSE 100, PSNR = 10 log10(650.25) = 28.131 dB.
    const fs::path dir = outputDir();
    pb::image::writePng((dir / "t.png").string(), grey(20, 12, 110));
    pb::image::writePng((dir / "r.png").string(), grey(20, 12, 100));
    const auto r = runProbebench({"compare", "--test", (dir / "t.png").string(), "--reference",
                                  (dir / "r.png").string(), "--heatmap",
                                  (dir / "heat.png").string(), "--ppd", "40"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* text : {"PSNR       28.131 dB", "SSIM", "FLIP       mean", "40.0 pixels"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << " in:\n" << r.output;
    const pb::image::Image8 heat = pb::image::readPng((dir / "heat.png").string());
    EXPECT_EQ(heat.width, 20);
    EXPECT_EQ(heat.height, 12);
    EXPECT_GT(int(heat.pixels[0]) + heat.pixels[1] + heat.pixels[2], 0) << "error shown as black";
}

TEST(CompareCli, MissingFileIsAOneLineError) {
    const fs::path dir = outputDir();
    pb::image::writePng((dir / "a.png").string(), grey(4, 4, 0));
    const auto r =
        runProbebench({"compare", "--test", (dir / "nope.png").string(), "--reference",
                       (dir / "a.png").string(), "--heatmap", (dir / "heat.png").string()});
    compareExpectOneLineError(r, "nope.png");
    EXPECT_FALSE(fs::exists(dir / "heat.png"));
}

TEST(CompareCli, SizeMismatchNamesBothFiles) {
    const fs::path dir = outputDir();
    pb::image::writePng((dir / "small.png").string(), grey(4, 4, 0));
    pb::image::writePng((dir / "big.png").string(), grey(8, 4, 0));
    const auto r =
        runProbebench({"compare", "--test", (dir / "small.png").string(), "--reference",
                       (dir / "big.png").string(), "--heatmap", (dir / "heat.png").string()});
    compareExpectOneLineError(r, "small.png");
    EXPECT_NE(r.output.find("big.png"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("4x4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("8x4"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "heat.png"));
}

TEST(CompareCli, RejectsANonPositivePpdAndExplainsOptions) {
    const fs::path dir = outputDir();
    pb::image::writePng((dir / "a.png").string(), grey(4, 4, 0));
    const auto bad = runProbebench({"compare", "--test", (dir / "a.png").string(), "--reference",
                                    (dir / "a.png").string(), "--ppd", "0"});
    EXPECT_NE(bad.exitCode, 0) << bad.output;
    EXPECT_FALSE(bad.crashed);
    EXPECT_NE(bad.output.find("--ppd"), std::string::npos) << bad.output;
    const auto help = runProbebench({"compare", "--help"});
    EXPECT_EQ(help.exitCode, 0);
    for (const char* opt : {"--test", "--reference", "--ppd", "--heatmap", "--json"})
        EXPECT_NE(help.output.find(opt), std::string::npos) << opt;
}
