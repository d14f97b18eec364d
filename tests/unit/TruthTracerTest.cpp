// The path tracer's contract beyond the closed forms: deterministic for any thread count,
// one-line errors for bad settings and blind views, a black image and a note without light,
// the alias table's probabilities, the CPU tonemap, and the cache key and files.
#include "scene/SceneBuilder.h"
#include "core/Error.h"
#include "truth/TruthCache.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

using namespace pb;

namespace {

scene::Scene litBox() {
    scene::Scene s;
    s.name = "box";
    s.sun.enabled = false;
    s.sky.radiance = glm::vec3(0.0f);
    scene::SceneBuilder b(s);
    int m = b.material("m", glm::vec3(0.7f, 0.5f, 0.3f), glm::vec3(0.5f));
    s.materials[size_t(m)].doubleSided = true;
    b.box("box", glm::vec3(-1.0f), glm::vec3(1.0f), m);
    return s;
}

const scene::View kInside{"in", {0.2f, 0.1f, 0.0f}, {0.0f, 0.0f, -1.0f}, 70.0f};

std::string outDir(const std::string& name) {
    auto d = std::filesystem::path(PB_TEST_OUTPUT_DIR) / name;
    std::filesystem::remove_all(d);
    return d.string();
}

} // namespace

TEST(TruthTracer, SameImageForAnyThreadCount) {
    scene::Scene s = litBox();
    truth::TruthSettings ts;
    ts.width = 24;
    ts.height = 16;
    ts.spp = 8;
    ts.threads = 1;
    auto one = truth::renderTruth(s, kInside, ts);
    ts.threads = 3;
    auto three = truth::renderTruth(s, kInside, ts);
    EXPECT_EQ(one.hdr.pixels, three.hdr.pixels);
    EXPECT_EQ(one.noise.standardError, three.noise.standardError);
    ts.seed = 2; // and the seed matters
    EXPECT_NE(truth::renderTruth(s, kInside, ts).hdr.pixels, one.hdr.pixels);
}

TEST(TruthTracer, StandardErrorHalvesWithFourTimesTheSamples) {
    scene::Scene s = litBox();
    truth::TruthSettings ts;
    ts.width = ts.height = 16;
    ts.spp = 16;
    const truth::TruthNoise n16 = truth::renderTruth(s, kInside, ts).noise;
    ts.spp = 64;
    const truth::TruthNoise n64 = truth::renderTruth(s, kInside, ts).noise;
    EXPECT_NEAR(n64.standardError / n16.standardError, 0.5, 0.1);
    EXPECT_NEAR(n64.pixelRelativeStandardError / n16.pixelRelativeStandardError, 0.5, 0.1);
    EXPECT_NEAR(n64.relativeMseNoiseFloor / n16.relativeMseNoiseFloor, 0.25, 0.05);
}

TEST(TruthTracer, BadSettingsAndBlindViewsAreOneLineErrors) {
    scene::Scene s = litBox();
    truth::TruthSettings ts;
    ts.width = ts.height = 4;
    ts.spp = 0;
    EXPECT_THROW(truth::renderTruth(s, kInside, ts), Error);
    ts.spp = 1;
    ts.maxDepth = 0;
    EXPECT_THROW(truth::renderTruth(s, kInside, ts), Error);
    ts.maxDepth = 4;
    try {
        // Outside the box, looking away from it.
        truth::renderTruth(s, scene::View{"away", {0, 0, 5}, {0, 0, 10}, 60.0f}, ts);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("sees no geometry"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
    EXPECT_THROW(truth::renderTruth(s, scene::View{"x", {1, 1, 1}, {1, 1, 1}, 60.0f}, ts), Error);
}

TEST(TruthTracer, NoLightGivesABlackImageAndANote) {
    scene::Scene s = litBox();
    s.materials[0].emissive = glm::vec3(0.0f);
    EXPECT_FALSE(truth::sceneHasLight(s));
    truth::TruthSettings ts;
    ts.width = ts.height = 4;
    ts.spp = 2;
    auto r = truth::renderTruth(s, kInside, ts);
    EXPECT_FALSE(r.note.empty());
    for (std::size_t i = 0; i < r.hdr.pixels.size(); ++i)
        EXPECT_EQ(r.hdr.pixels[i], i % 4 == 3 ? 1.0f : 0.0f);
}

TEST(TruthTracer, SingleSidedBackFacesAreCulledForCameraRaysOnly) {
    // One-sided walls facing out: from inside the camera sees through them, as the rasterizer
    // does, to the black sky, while light rays still hit them.
    scene::Scene s;
    s.name = "outward";
    s.sun.enabled = false;
    s.sky.radiance = glm::vec3(1.0f);
    scene::SceneBuilder b(s);
    b.box("box", glm::vec3(-1.0f), glm::vec3(1.0f), b.material("m", glm::vec3(0.5f)));
    b.box("inner", glm::vec3(-0.1f, -0.1f, -0.5f), glm::vec3(0.1f, 0.1f, -0.3f), 0);
    truth::TruthSettings ts;
    ts.width = ts.height = 9;
    ts.spp = 16;
    auto r = truth::renderTruth(s, scene::View{"in", {0, 0, 0}, {0, 0, -1}, 120.0f}, ts);
    EXPECT_FLOAT_EQ(r.hdr.at(0, 0, 0), 1.0f); // the sky through the culled wall
    // The small box in the middle is lit only by the sky that leaks through... nothing: the
    // enclosing box blocks every light ray.
    EXPECT_FLOAT_EQ(r.hdr.at(4, 4, 0), 0.0f);
}

TEST(TruthTonemap, IsTheCompositePassOnTheCpu) {
    image::ImageF hdr;
    hdr.width = 4;
    hdr.height = 1;
    hdr.pixels = {0, 0, 0, 1, 1e6f, 1e6f, 1e6f, 1, 0.5f, 0.5f, 0.5f, 1, NAN, 1, 1, 1};
    image::Image8 out = truth::tonemap(hdr, 2.0f);
    EXPECT_EQ(out.at(0, 0, 0), 0);
    EXPECT_EQ(out.at(1, 0, 0), 255);
    // x = 1 (0.5 x exposure 2): ACES fit 2.54 / 3.16 = 0.8038, sRGB 0.9107 -> 232.
    double aces = (1.0 * (2.51 + 0.03)) / (1.0 * (2.43 + 0.59) + 0.14);
    double srgb = 1.055 * std::pow(aces, 1.0 / 2.4) - 0.055;
    EXPECT_EQ(out.at(2, 0, 0), int(std::lround(srgb * 255.0)));
    EXPECT_EQ(out.at(3, 0, 1), 0); // NaN anywhere in the pixel: black
}

TEST(TruthCache, KeyFollowsTheInputsAndFilesRoundTrip) {
    scene::Scene s = litBox();
    truth::TruthSettings ts;
    ts.width = ts.height = 4;
    ts.spp = 4;
    const std::uint64_t h = truth::truthInputHash(s, kInside, ts);
    truth::TruthSettings more = ts;
    more.spp = 8;
    EXPECT_NE(truth::truthInputHash(s, kInside, more), h);
    truth::TruthSettings threads = ts;
    threads.threads = 7;
    EXPECT_EQ(truth::truthInputHash(s, kInside, threads), h);
    scene::View moved = kInside;
    moved.fovYDegrees += 1.0f;
    EXPECT_NE(truth::truthInputHash(s, moved, ts), h);
    scene::Scene brighter = s;
    brighter.materials[0].emissive *= 2.0f;
    EXPECT_NE(truth::truthInputHash(brighter, kInside, ts), h);

    const std::string dir = outDir("truth-cache");
    EXPECT_FALSE(truth::loadCachedTruth(dir, h, ts).has_value());
    auto r = truth::renderTruth(s, kInside, ts);
    truth::storeCachedTruth(dir, h, r);
    auto back = truth::loadCachedTruth(dir, h, ts);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(back->hdr.pixels.size(), r.hdr.pixels.size());
    for (std::size_t i = 0; i < r.hdr.pixels.size(); ++i)
        EXPECT_EQ(back->hdr.pixels[i], r.hdr.pixels[i]);
    EXPECT_EQ(back->noise.standardError, r.noise.standardError);
    // A damaged sidecar is recomputed, not trusted.
    std::string pfm = truth::truthCachePath(dir, h);
    std::filesystem::resize_file(pfm.substr(0, pfm.size() - 4) + ".json", 5);
    EXPECT_FALSE(truth::loadCachedTruth(dir, h, ts).has_value());
}
