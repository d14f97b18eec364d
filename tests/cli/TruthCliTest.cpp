// `probebench truth` as a user runs it: files and JSON written, the cache reused, one-line
// errors with nothing written for bad input, a black image and a note without light.
#include "image/Image.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// exit 1: the scene or view fails; 2: an option's value is out of range (a usage error).
void truthExpectOneLineError(const CommandResult& r, const std::string& mustName, int exit = 1) {
    EXPECT_FALSE(r.crashed) << r.output;
    EXPECT_EQ(r.exitCode, exit) << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(mustName), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

nlohmann::json truthReadJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in, nullptr, false);
}

std::vector<std::string> small(const fs::path& dir) {
    return {"truth", "--scene", "cornell", "--view", "front", "--width", "32", "--height", "18",
            "--spp", "8", "--cache-dir", (dir / "cache").string()};
}

} // namespace

TEST(TruthCli, WritesHdrPngAndJsonThenReusesTheCache) {
    const fs::path dir = outputDir();
    auto args = small(dir);
    args.insert(args.end(), {"--out-hdr", (dir / "t.pfm").string(), "--out", (dir / "t.png").string(),
                             "--json", (dir / "t.json").string()});
    auto r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("standard error"), std::string::npos) << r.output;
    auto hdr = pb::image::readPfm((dir / "t.pfm").string());
    EXPECT_EQ(hdr.width, 32);
    auto png = pb::image::readPng((dir / "t.png").string());
    EXPECT_EQ(png.height, 18);
    auto j = truthReadJson(dir / "t.json");
    ASSERT_FALSE(j.is_discarded());
    EXPECT_FALSE(j["cached"].get<bool>());
    EXPECT_GT(j["mean_luminance"].get<double>(), 0.0);
    EXPECT_GT(j["standard_error"].get<double>(), 0.0);
    EXPECT_LT(j["relative_standard_error"].get<double>(), 0.05);
    EXPECT_TRUE(fs::exists(j["cache_file"].get<std::string>()));

    r = runProbebench(args);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto again = truthReadJson(dir / "t.json");
    EXPECT_TRUE(again["cached"].get<bool>());
    EXPECT_EQ(again["mean_luminance"], j["mean_luminance"]);
}

TEST(TruthCli, BadInputIsAOneLineErrorAndWritesNothing) {
    const fs::path dir = outputDir();
    const std::string out = (dir / "bad.pfm").string();
    auto args = small(dir);
    args.insert(args.end(), {"--out-hdr", out});
    auto spp0 = args;
    spp0[10] = "0";
    truthExpectOneLineError(runProbebench(spp0), "--spp", 2);
    auto blind = args;
    blind.insert(blind.end(), {"--camera", "0,1,5,0,1,10"}); // outside the box, looking away
    truthExpectOneLineError(runProbebench(blind), "sees no geometry");
    auto view = args;
    view[4] = "nowhere";
    truthExpectOneLineError(runProbebench(view), "nowhere");
    EXPECT_FALSE(fs::exists(out));
}

TEST(TruthCli, NoLightGivesABlackImageAndANote) {
    const fs::path dir = outputDir();
    auto r = runProbebench({"truth", "--scene", "rooms", "--sun", "off", "--sky", "0,0,0", "--width", "16",
                            "--height", "9", "--spp", "2", "--no-cache", "--out-hdr",
                            (dir / "black.pfm").string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("note:"), std::string::npos) << r.output;
    auto hdr = pb::image::readPfm((dir / "black.pfm").string());
    EXPECT_TRUE(std::all_of(hdr.pixels.begin(), hdr.pixels.end(), [](float v) { return v == 0.0f; }));
}
