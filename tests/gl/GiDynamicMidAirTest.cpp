// Dynamic objects in the air lit from a sparse bake (issue 18, item 3): `rooms_dynamic`'s three
// boxes hang where no surface keeps a probe (its view `dynamic` shows two), so a sparse set
// lights them through its free-space lattice and the stand-ins for its absent probes
// (probes/AbsentProbeFill.h). Both dynamic paths, gi.dynamic=per_pixel and sh, must light every
// pixel of them, within the stated tolerance of the dense set of the same grid, as the mean
// relative difference of the indirect irradiance over the objects' pixels:
// - per_pixel 15%: every pixel is its own mid-air lookup, so the mean over the objects is the
//   mid-air lookups' mean (tests/unit/MidAirLookupTest.cpp: 15%);
// - sh 25%: every pixel of an object shares one L1 fit taken around the object's centre, so the
//   three objects are three draws of the lookup error, not hundreds; the mid-air lookups' p90
//   is 0.18-0.23 on the built-in scenes (MidAirLookupTest's printout), measured here 0.18.
// Plus a golden image of the scene lit by the sparse bake.
#include "gl/GBufferSurfaces.h"
#include "gl/GlTestFixture.h"
#include "gl/GoldenCheck.h"
#include "gl/LambertIrradiance.h"

#include "frame/FrameRenderer.h"
#include "frame/Readback.h"
#include "passes/GiApplyPass.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/Baker.h"
#include "raytrace/RayScene.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"
#include "support/ImageCompare.h"
#include "support/TestEnv.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fs = std::filesystem;

namespace pb::test {
namespace {

constexpr int kGiDynamicMidAirW = 160, kGiDynamicMidAirH = 90;

const scene::Scene& dynamicScene() {
    static const scene::Scene s = scene::makeBuiltinScene("rooms_dynamic");
    return s;
}

// The dense bake of one root volume over the static bounds, and the same set stored sparse.
struct Bakes {
    probes::ProbeSet dense, sparse;
};
const Bakes& bakes() {
    static const Bakes b = [] {
        const scene::Scene& s = dynamicScene();
        probes::BakeRequest r;
        r.volumes.push_back(
            probes::fitAutoVolume(raytrace::staticBakeBounds(s), 0.0f, 1500).volume);
        r.scenarios = probes::resolveScenarios({"day"}, {}, s);
        r.settings.raysPerProbe = 64;
        // These tests compare storage and lookups, not light: two passes, one round of rays
        // each. Measured (AMD EPYC) over bounce settings:
        // - the sh case's figure follows the noise rounds on the boxes' dim faces, where the
        //   object's one L1 fit can ring to black: without rounds 0.05 / 0.08 / 0.13 / 0.07
        //   (converged, 1, 2, 3 passes), with the default 3% target 0.15 / 0.09 / 1.33 / 0.49.
        //   Which probes take more rounds follows the CPU's last bits, so with rounds the
        //   figure would not hold on another CPU (why the rounds move the fit that much is
        //   open); the per_pixel case stayed within 0.04 - 0.13 either way;
        // - the behind-surface fade (GiDynamicPerPixelTest) moves 196 of the boxes' 432 pixels
        //   by over 1% after two passes, 0 - 7 after converged light, which is smoother.
        r.settings.bounces = 2;
        r.settings.noiseTarget = 0.0f;
        Bakes out{probes::bakeProbes(s, r), {}};
        out.sparse = out.dense;
        probes::applySparseStorage(out.sparse, raytrace::staticBakeTriangles(s));
        return out;
    }();
    return b;
}

// The indirect irradiance of every dynamic pixel (GBuffer flag bit 0): the lighting's
// indirect-only output x pi / albedo; and how many of them the probes lit at all.
struct DynamicPixels {
    std::vector<glm::vec3> irradiance;
    int unlit = 0;
};
DynamicPixels renderDynamic(const probes::ProbeSet& set, const std::string& mode) {
    const scene::Scene& s = dynamicScene();
    render::GiOptions gi;
    gi.probes = &set;
    gi.profile.applyOverride("gi.target_format=rgba32f");
    gi.profile.applyOverride("gi.dynamic=" + mode);
    render::FrameSettings fs = render::defaultFrameSettings(s);
    fs.indirectOnly = true;
    render::FrameRenderer r(s, fs, gi);
    r.render(render::makeRenderView(*s.findView("dynamic"), s.worldBounds(), kGiDynamicMidAirW,
                                    kGiDynamicMidAirH));
    const image::ImageF radiance = r.readRadiance();
    const image::Image8 albedo = render::readRgba8(r.targets()->gbuffer.channel(0));
    const image::Image8 flags = render::readRgba8(r.targets()->gbuffer.channel(3));
    DynamicPixels d;
    for (int y = 0; y < kGiDynamicMidAirH; ++y)
        for (int x = 0; x < kGiDynamicMidAirW; ++x) {
            if (!(flags.at(x, y, 0) & 1u)) continue;
            const glm::vec3 e = lambertIrradiance(radiance, albedo, x, y);
            d.irradiance.push_back(e);
            d.unlit += e.x + e.y + e.z > 0.0f ? 0 : 1;
        }
    return d;
}

float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

class GiDynamicMidAirTest : public GlTest, public ::testing::WithParamInterface<const char*> {};
class GiDynamicPerPixelTest : public GlTest {};

TEST_P(GiDynamicMidAirTest, SparseBakeLightsDynamicObjectsLikeTheDenseOne) {
    const Bakes& b = bakes();
    ASSERT_LT(b.sparse.storedCount(), b.sparse.probeCount()) << "nothing absent: vacuous";
    const DynamicPixels dense = renderDynamic(b.dense, GetParam());
    const DynamicPixels sparse = renderDynamic(b.sparse, GetParam());
    ASSERT_EQ(dense.irradiance.size(), sparse.irradiance.size());
    double sum = 0.0, worst = 0.0, mean = 0.0;
    for (const glm::vec3& e : dense.irradiance)
        mean += luminance(e) / double(dense.irradiance.size());
    for (std::size_t i = 0; i < dense.irradiance.size(); ++i) {
        const double ld = luminance(dense.irradiance[i]), ls = luminance(sparse.irradiance[i]);
        // Near-black pixels judged against a tenth of the objects' mean (MidAirLookupTest).
        const double rel = std::abs(ls - ld) / std::max(ld, 0.1 * mean);
        sum += rel;
        worst = std::max(worst, rel);
    }
    const double meanRel = sum / double(std::max<std::size_t>(dense.irradiance.size(), 1));
    std::printf("[ dynamic mid-air ] gi.dynamic=%s: %zu dynamic pixels, unlit %d (dense %d); "
                "sparse vs dense: mean relative difference %.4f, worst %.4f\n",
                GetParam(), sparse.irradiance.size(), sparse.unlit, dense.unlit, meanRel, worst);
    ASSERT_GT(sparse.irradiance.size(), 300u) << "the view must show the dynamic boxes";
    EXPECT_EQ(dense.unlit, 0) << "a dynamic pixel is dark in the dense bake: nothing to compare";
    EXPECT_EQ(sparse.unlit, 0) << "a dynamic pixel is dark in the sparse bake";
    EXPECT_LE(meanRel, std::string(GetParam()) == "sh" ? 0.25 : 0.15);
}

INSTANTIATE_TEST_SUITE_P(Modes, GiDynamicMidAirTest, ::testing::Values("per_pixel", "sh"));

// gi.dynamic=per_pixel (the default): a dynamic object's pixel is a mid-air lookup, without the
// behind-surface fade that static pixels get (GI_DYNAMIC_UNFADED; ProbeSampler.h
// midAirLookup()). The apply pass's GI target against the CPU sampler at every pixel's GBuffer
// surface, each with its own options; and the fade must matter on enough dynamic pixels for
// the comparison to tell the two apart.
TEST_F(GiDynamicPerPixelTest, PerPixelDynamicPixelsSkipTheBehindFadeAsTheCpuDoes) {
    const scene::Scene& s = dynamicScene();
    render::GiOptions gi;
    gi.probes = &bakes().dense;
    gi.profile.applyOverride("gi.target_format=rgba32f");
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    const render::RenderView view = render::makeRenderView(*s.findView("dynamic"), s.worldBounds(),
                                                           kGiDynamicMidAirW, kGiDynamicMidAirH);
    r.render(view);
    checkNoGlErrors("rendering");
    const std::vector<GBufferSurface> surfaces = gbufferSurfaces(r, view);
    ASSERT_NE(giTarget(r), nullptr) << "no GI apply pass";
    const image::ImageF target = render::readFloat(*giTarget(r));
    const probes::ProbeSampler cpu(bakes().dense, 0);
    int dynamic = 0, fadeMatters = 0, worse = 0, surface = 0;
    for (int y = 0; y < kGiDynamicMidAirH; ++y)
        for (int x = 0; x < kGiDynamicMidAirW; ++x) {
            const GBufferSurface& px =
                surfaces[std::size_t(y) * kGiDynamicMidAirW + std::size_t(x)];
            if (px.sky) continue;
            ++surface;
            const bool isDynamic = (px.flags & 1u) != 0;
            const probes::IrradianceSample faded = cpu.sample(px.world, px.normal, -px.rel);
            const probes::IrradianceSample expected =
                isDynamic ? cpu.sample(px.world, px.normal, -px.rel, probes::midAirLookup())
                          : faded;
            double rel = std::abs(double(target.at(x, y, 3)) - expected.weight);
            for (int k = 0; k < 3; ++k)
                rel = std::max(rel, std::abs(double(target.at(x, y, k)) - expected.irradiance[k]) /
                                        std::max(double(expected.irradiance[k]), 1e-3));
            worse += rel > 1e-3 ? 1 : 0;
            if (!isDynamic) continue;
            ++dynamic;
            const float lf = luminance(faded.irradiance), le = luminance(expected.irradiance);
            fadeMatters += std::abs(lf - le) > 0.01f * std::max(le, 1e-3f) ? 1 : 0;
        }
    std::printf("[ dynamic unfaded ] %d surface pixels, %d dynamic (%d where the fade would move "
                "E by > 1%%); %d pixels off the CPU's lookup by > 1e-3\n",
                surface, dynamic, fadeMatters, worse);
    ASSERT_GT(dynamic, 300) << "the view must show the dynamic boxes";
    EXPECT_GT(fadeMatters, dynamic / 10) << "the fade changes too few pixels: vacuous";
    // Depth reconstruction may put a pixel on a cell boundary's other side (GiFrameTest).
    EXPECT_LE(worse, surface / 1000);
}

// The scene lit by its sparse bake by default (gi.dynamic's default), against
// tests/golden/rooms_dynamic_dynamic_gi.png with the golden tolerance (tests/README.md). The
// probes come from this test's bake: bakes differ in the last bits across CPUs (Embree's ISA),
// far below the tolerance.
class GiDynamicGolden : public GlTest {};

TEST_F(GiDynamicGolden, SparseBakeLitSceneMatchesItsGolden) {
    const scene::Scene& s = dynamicScene();
    render::GiOptions gi;
    gi.probes = &bakes().sparse;
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    r.render(render::makeRenderView(*s.findView("dynamic"), s.worldBounds(), 320, 180));
    const image::Image8 actual = r.readOutput();
    checkNoGlErrors("rendering");
    const fs::path golden = goldenDir() / "rooms_dynamic_dynamic_gi.png";
    if (updateOrCompareGolden(actual, golden)) GTEST_SKIP() << "golden written: " << golden;
}

} // namespace
} // namespace pb::test
