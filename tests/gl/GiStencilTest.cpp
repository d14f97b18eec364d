// gi.multi_volume=stencil on three nested volumes (GiNestedVolumes.h): every covered pixel of
// the GI target is evaluated exactly once, by the smallest volume containing it, with the
// camera outside every volume, inside the middle one and inside the inner one, at every
// gi.resolution; the image equals naive's; every visible volume but the last drawn marks its
// pixels; volumes outside the frustum are culled. Pixel counts come from the
// pass's counting mode (GiApplyPass::setCountPixels: an "evaluated" attachment per volume).
#include "gl/GiNestedVolumes.h"
#include "gl/GlTestFixture.h"

#include "frame/Readback.h"
#include "profile/GiVolumeLod.h"
#include "probes/ProbeSampler.h"
#include "probes/sh/ShIrradiance.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pb::test {
namespace {

constexpr int kGiStencilW = 160, kGiStencilH = 90;

struct StencilFrame {
    image::ImageF gi;
    render::GiPassStats stats;
    render::RenderView view;
};

render::GiApplyPass* giStencilApplyPass(render::FrameRenderer& r) {
    for (const auto& p : r.passes())
        if (auto* gi = dynamic_cast<render::GiApplyPass*>(p.get())) return gi;
    return nullptr;
}

StencilFrame renderStencilNested(const NestedCamera& cam, const std::string& multiVolume,
                                 const std::string& resolution, const std::string& dumpDir = "",
                                 bool hugeRoot = false, const std::string& technique = "ddgi") {
    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &nestedVolumeProbes(hugeRoot);
    // The synthetic set has no SH probes: project its maps as the bake does.
    static const probes::ProbeSet withSh = [] {
        probes::ProbeSet set = nestedVolumeProbes(false);
        set.sh = probes::projectSetToSh(set, 1);
        return set;
    }();
    if (technique != "ddgi") gi.probes = &withSh;
    gi.profile.applyOverride("gi.target_format=rgba32f");
    gi.profile.applyOverride("gi.multi_volume=" + multiVolume);
    gi.profile.applyOverride("gi.resolution=" + resolution);
    gi.profile.applyOverride("gi.technique=" + technique);
    gi.profile.applyOverride("gi.sh_leak=weight");
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    render::GiApplyPass* pass = giStencilApplyPass(r);
    pass->setCountPixels(true);
    StencilFrame f;
    f.view = render::makeRenderView(cam.view, s.worldBounds(), kGiStencilW, kGiStencilH);
    r.render(f.view);
    f.gi = render::readFloat(*pass->target());
    f.stats = pass->stats();
    if (!dumpDir.empty()) r.dumpGBuffer(dumpDir);
    return f;
}

std::string shadedName(const render::GiPassStats& s, size_t texel) {
    const int v = s.shadedBy[texel];
    return v < 0 ? "" : s.volumes[size_t(v)].name;
}

const render::GiVolumeStats* volumeStats(const render::GiPassStats& s, const std::string& name) {
    for (const auto& v : s.volumes)
        if (v.name == name) return &v;
    return nullptr;
}

void printCounts(const char* what, const StencilFrame& f) {
    std::printf("  %-8s", what);
    for (const auto& v : f.stats.volumes)
        std::printf(" %s=%lld%s%s%s", v.name.c_str(), static_cast<long long>(v.evaluatedPixels),
                    v.culled ? "(culled)" : "", v.fillPass ? "(mark)" : "",
                    v.fullScreen ? "(full-screen)" : "");
    std::printf("; evaluations %lld for %lld covered texels\n",
                static_cast<long long>(f.stats.totalEvaluations()),
                static_cast<long long>(f.stats.coveredPixels()));
}

class GiStencilTest : public GlTest {};

// The SH technique (issue 19) reuses the volume draws, discard and stencil marks: with it too,
// stencil shades each covered texel once, by naive's volume, and the image is naive's.
TEST_F(GiStencilTest, TheShTechniqueShadesLikeNaiveUnderStencil) {
    for (const char* technique : {"sh_l1", "sh_l2"})
        for (const NestedCamera& cam : nestedCameras()) {
            SCOPED_TRACE(std::string(technique) + ", camera " + cam.name);
            const StencilFrame naive =
                renderStencilNested(cam, "naive", "full", "", false, technique);
            const StencilFrame stencil =
                renderStencilNested(cam, "stencil", "full", "", false, technique);
            ASSERT_EQ(stencil.stats.evaluations.size(), naive.stats.evaluations.size());
            int wrongCount = 0, wrongVolume = 0;
            for (size_t i = 0; i < naive.stats.evaluations.size(); ++i) {
                wrongCount += stencil.stats.evaluations[i] != (naive.stats.evaluations[i] > 0);
                wrongVolume += shadedName(stencil.stats, i) != shadedName(naive.stats, i);
            }
            EXPECT_EQ(wrongCount, 0);
            EXPECT_EQ(wrongVolume, 0);
            EXPECT_GT(stencil.stats.coveredPixels(),
                      stencil.stats.width * stencil.stats.height / 3);
            float maxAbs = 0, maxValue = 0;
            for (size_t i = 0; i < naive.gi.pixels.size(); ++i) {
                maxAbs = std::max(maxAbs, std::abs(naive.gi.pixels[i] - stencil.gi.pixels[i]));
                maxValue = std::max(maxValue, std::abs(naive.gi.pixels[i]));
            }
            EXPECT_GT(maxValue, 0.0f) << "the SH lookup lit nothing";
            EXPECT_LE(maxAbs, 1e-3f * 1.3f) << "GI target differs from naive's";
        }
}

TEST_F(GiStencilTest, EveryCoveredPixelIsEvaluatedOnceByTheSmallestVolume) {
    const std::vector<std::string> nesting{"sun_patch", "sunlit_room", "building"};
    for (const NestedCamera& cam : nestedCameras())
        for (const char* res : {"full", "half", "quarter"}) {
            SCOPED_TRACE(std::string(cam.name) + ", gi.resolution=" + res);
            const StencilFrame naive = renderStencilNested(cam, "naive", res);
            const StencilFrame stencil = renderStencilNested(cam, "stencil", res);
            std::printf("[ stencil ] camera %s, gi.resolution=%s (%dx%d):\n", cam.name, res,
                        stencil.stats.width, stencil.stats.height);
            printCounts("naive", naive);
            printCounts("stencil", stencil);
            ASSERT_TRUE(stencil.stats.counted);
            ASSERT_EQ(stencil.stats.evaluations.size(), naive.stats.evaluations.size());
            int wrongCount = 0, wrongVolume = 0, overdrawn = 0;
            std::map<std::string, int> shaded;
            for (size_t i = 0; i < naive.stats.evaluations.size(); ++i) {
                const int expected = naive.stats.evaluations[i] > 0 ? 1 : 0;
                wrongCount += stencil.stats.evaluations[i] != expected;
                wrongVolume += shadedName(stencil.stats, i) != shadedName(naive.stats, i);
                overdrawn += naive.stats.evaluations[i] > 1;
                ++shaded[shadedName(stencil.stats, i)];
            }
            EXPECT_EQ(wrongCount, 0) << "texels not evaluated exactly once where naive covers";
            EXPECT_EQ(wrongVolume, 0) << "texels shaded by another volume than naive's last";
            EXPECT_EQ(stencil.stats.totalEvaluations(), stencil.stats.coveredPixels());
            EXPECT_GT(stencil.stats.coveredPixels(),
                      stencil.stats.width * stencil.stats.height / 3);
            if (std::string(cam.culled).empty()) {
                // Every volume takes pixels, and naive pays for overlap.
                for (const std::string& v : nesting)
                    EXPECT_GT(shaded[v], 0) << v << " shades nothing: the case tests little";
                EXPECT_GT(overdrawn, 0);
                EXPECT_GT(naive.stats.totalEvaluations(), stencil.stats.totalEvaluations());
            }

            // Every visible volume but the last drawn marks what it shaded.
            std::string lastVisible; // drawn last: largest not culled
            for (const std::string& n : nesting)
                if (n != cam.culled) lastVisible = n;
            const auto inside = std::find(nesting.begin(), nesting.end(), cam.inside);
            for (size_t k = 0; k < nesting.size(); ++k) {
                const render::GiVolumeStats* v = volumeStats(stencil.stats, nesting[k]);
                ASSERT_NE(v, nullptr);
                const bool eyeInside =
                    inside != nesting.end() && k >= size_t(inside - nesting.begin());
                EXPECT_EQ(v->culled, nesting[k] == cam.culled) << nesting[k];
                if (v->culled) continue;
                EXPECT_EQ(v->cameraInside, eyeInside) << nesting[k];
                EXPECT_EQ(v->fillPass, nesting[k] != lastVisible) << nesting[k];
            }
            EXPECT_EQ(stencil.stats.volumes.front().name, "sun_patch") << "smallest first";

            // The same image: the same lookups by the same volumes.
            float maxAbs = 0;
            for (size_t i = 0; i < naive.gi.pixels.size(); ++i)
                maxAbs = std::max(maxAbs, std::abs(naive.gi.pixels[i] - stencil.gi.pixels[i]));
            EXPECT_LE(maxAbs, 1e-3f * 1.3f) << "GI target differs from naive's";
        }
}

// A root reaching past the far plane cannot be depth-tested by its back faces (far clipping
// would drop them): with the camera inside, it is drawn full-screen; still once per pixel.
TEST_F(GiStencilTest, ABoxPastTheFarPlaneIsDrawnFullScreen) {
    for (const NestedCamera& cam : nestedCameras()) {
        if (std::string(cam.name) != "inside_middle") continue;
        const StencilFrame naive = renderStencilNested(cam, "naive", "full", "", true);
        const StencilFrame stencil = renderStencilNested(cam, "stencil", "full", "", true);
        std::printf("[ stencil ] huge root, camera %s:\n", cam.name);
        printCounts("naive", naive);
        printCounts("stencil", stencil);
        const render::GiVolumeStats* root = volumeStats(stencil.stats, "building");
        ASSERT_NE(root, nullptr);
        EXPECT_TRUE(root->cameraInside);
        EXPECT_TRUE(root->fullScreen);
        EXPECT_GT(root->evaluatedPixels, 0);
        int wrong = 0;
        for (size_t i = 0; i < naive.stats.evaluations.size(); ++i)
            wrong += stencil.stats.evaluations[i] != (naive.stats.evaluations[i] > 0 ? 1 : 0) ||
                     shadedName(stencil.stats, i) != shadedName(naive.stats, i);
        EXPECT_EQ(wrong, 0);
        EXPECT_EQ(naive.gi.pixels, stencil.gi.pixels);
    }
}

// gi.volume_lod: an omitted volume is neither uploaded nor drawn; its pixels go to its parent.
TEST_F(GiStencilTest, AnOmittedVolumeIsNotDrawn) {
    const scene::Scene& s = giTestScene();
    const probes::ProbeSet& set = nestedVolumeProbes();
    render::GiOptions gi;
    gi.probes = &set;
    gi.profile.applyOverride("gi.multi_volume=stencil");
    gi.profile.applyOverride("gi.volume_lod=omit:sun_patch");
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    giStencilApplyPass(r)->setCountPixels(true);
    r.render(
        render::makeRenderView(nestedCameras()[1].view, s.worldBounds(), kGiStencilW, kGiStencilH));
    const render::GiPassStats& stats = giStencilApplyPass(r)->stats();
    ASSERT_EQ(stats.volumes.size(), 2u);
    for (const auto& v : stats.volumes)
        EXPECT_NE(v.name, "sun_patch");
    EXPECT_EQ(r.gpuProbes()->bytes(), render::GpuProbes(set, 0).bytes() -
                                          profile::gpuVolumeBytes(set.volumes[2], set.format()));
    EXPECT_EQ(stats.totalEvaluations(), stats.coveredPixels());
}

// The stencil's volume per pixel is the CPU sampler's choice at the pixel's surface point
// (full resolution; depth reconstruction on the two sides may disagree on a boundary pixel).
TEST_F(GiStencilTest, TheShadingVolumeIsTheCpuSamplersChoice) {
    const std::filesystem::path dir =
        std::filesystem::path(PB_TEST_OUTPUT_DIR) / "gi_stencil_gbuffer";
    const probes::ProbeSampler cpu(nestedVolumeProbes(), 0);
    for (const NestedCamera& cam : nestedCameras()) {
        const StencilFrame f = renderStencilNested(cam, "stencil", "full", dir.string());
        const image::ImageF depth = image::readPfm((dir / "depth.pfm").string());
        int checked = 0, disagree = 0;
        for (int y = 0; y < kGiStencilH; ++y)
            for (int x = 0; x < kGiStencilW; ++x) {
                const float d = depth.at(x, y, 1);
                if (d >= 1.0f) continue;
                const int glRow = kGiStencilH - 1 - y;
                glm::vec4 relH = f.view.relFromClip *
                                 glm::vec4((x + 0.5f) / kGiStencilW * 2 - 1,
                                           (glRow + 0.5f) / kGiStencilH * 2 - 1, d * 2 - 1, 1);
                const glm::vec3 world =
                    glm::vec3(glm::dvec3(glm::vec3(relH) / relH.w) + f.view.eye);
                const int v = cpu.selectVolume(world);
                const std::string expected =
                    v < 0 ? "" : nestedVolumeProbes().volumes[size_t(v)].name;
                ++checked;
                disagree +=
                    shadedName(f.stats, size_t(glRow) * kGiStencilW + size_t(x)) != expected;
            }
        std::printf("[ stencil vs cpu ] %s: %d surface pixels, %d with another volume\n", cam.name,
                    checked, disagree);
        EXPECT_GT(checked, kGiStencilW * kGiStencilH / 2);
        EXPECT_LE(disagree, kGiStencilW * kGiStencilH / 1000) << cam.name;
    }
}

} // namespace
} // namespace pb::test
