// ./run.sh's first output (scripts/first-run.sh): the built-in Cornell box - closed, lit only by
// its ceiling panel - baked and rendered from its classic view with probe GI and with direct
// light only. The GI image must be lit nearly everywhere; the direct-only twin shows the panel
// and little else; so they differ where GI adds light. A re-run reuses the cached bake.
#include "image/Image.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

struct Lighting {
    double meanLuminance = 0; // linear radiance, Rec. 709 weights
    double litFraction = 0;   // pixels above 0.01
};

Lighting lighting(const pb::image::ImageF& img) {
    Lighting l;
    const size_t n = size_t(img.width) * size_t(img.height);
    for (size_t i = 0; i < n; ++i) {
        const float* p = &img.pixels[i * size_t(img.channels)];
        const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        l.meanLuminance += y / double(n);
        if (y > 0.01) l.litFraction += 1.0 / double(n);
    }
    return l;
}

} // namespace

TEST(FirstRun, TheGiImageIsLitAndDiffersFromItsDirectOnlyTwin) {
    const fs::path dir = outputDir();
    const CommandResult r = runCommand(
        {(sourceDir() / "scripts/first-run.sh").string(), binaryPath().string(), dir.string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"cornell.probes", "cornell_gi.png", "cornell_direct.png"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    const pb::image::ImageF gi = pb::image::readPfm((dir / "cornell_gi.pfm").string());
    const pb::image::ImageF direct = pb::image::readPfm((dir / "cornell_direct.pfm").string());
    ASSERT_EQ(gi.width, direct.width);
    ASSERT_EQ(gi.height, direct.height);
    const Lighting g = lighting(gi), d = lighting(direct);
    // With GI the walls, floor and boxes are lit: almost every pixel.
    EXPECT_GT(g.litFraction, 0.9);
    EXPECT_GT(g.meanLuminance, 0.1);
    // Direct only: the panel (the view sees it) and nothing it does not touch directly.
    EXPECT_GT(d.litFraction, 0.005) << "the classic view sees the light";
    EXPECT_LT(d.litFraction, 0.1);
    EXPECT_GT(g.meanLuminance, d.meanLuminance);
    // A second run bakes nothing: the probes in the output folder are up to date.
    const CommandResult again = runCommand(
        {(sourceDir() / "scripts/first-run.sh").string(), binaryPath().string(), dir.string()});
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("up to date"), std::string::npos) << again.output;
}
