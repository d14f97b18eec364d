// Debug views probes_irradiance / probes_visibility: a sphere at every probe, shaded by the
// probe's irradiance (white Lambertian: E / pi) or by its visibility (black when invalid).
// A 2x2x2 synthetic volume floats in the air of `rooms` in front of the camera; the pixel at
// each probe's projected centre is checked in the radiance target. Stored sparse (the invalid
// probe left out, every other tile one slot earlier), the spheres find their tiles through
// the state's tile code (shaders/common_ddgi_tile.glsl), as dense ones do.
#include "gl/GiSyntheticProbes.h"
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"
#include "probes/store/SparseStorage.h"

#include <cmath>
#include <cstdio>

namespace pb::test {
namespace {

constexpr int kGiDebugViewW = 320, kGiDebugViewH = 180;

struct SphereCheck {
    std::vector<glm::vec3> atProbe; // radiance at each probe's projected centre
    float exposure = 1.0f;
};

// Irradiance of probe (i, j, k): different along every axis, so a wrong column, row or
// layer shows.
glm::vec3 probeIrradiance(const glm::ivec3& p) {
    return glm::vec3(1.0f + float(p.x), 2.0f + float(p.y), 0.5f + float(p.z));
}

SphereCheck renderSpheres(render::GiDebugView view, bool sparse = false) {
    const scene::Scene& s = giTestScene();
    const scene::View& cam = *s.findView("sunlit_room");
    const glm::vec3 dir = glm::normalize(cam.target - cam.position);
    probes::ProbeSet set = syntheticProbes(
        {syntheticVolume("air", cam.position + 1.5f * dir, glm::vec3(0.3f), glm::ivec3(2))},
        [](int, const glm::vec3&, const glm::ivec3& p) { return probeIrradiance(p); },
        probes::StorageFormat::Rgba32f);
    set.states[0][0].valid = false;                                        // probe (0, 0, 0)
    if (sparse) probes::storeOnly(set, {std::vector<std::uint8_t>(8, 1)}); // all but invalid
    render::GiOptions gi;
    gi.probes = &set;
    gi.debugView = view;
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    const render::RenderView rv =
        render::makeRenderView(cam, s.worldBounds(), kGiDebugViewW, kGiDebugViewH);
    r.render(rv);
    const image::ImageF radiance = r.readRadiance();
    SphereCheck out;
    out.exposure = r.settings().exposure;
    const probes::ProbeVolume& v = set.volumes[0];
    for (int p = 0; p < v.probeCount(); ++p) {
        const glm::vec3 local = -v.halfExtents + glm::vec3(v.probeCoords(p)) * v.cellSize();
        const glm::vec4 clip = rv.clipFromRel * glm::vec4(rv.toRel(v.toWorld(local)), 1.0f);
        const int x = int((clip.x / clip.w * 0.5f + 0.5f) * kGiDebugViewW);
        const int y = kGiDebugViewH - 1 - int((clip.y / clip.w * 0.5f + 0.5f) * kGiDebugViewH);
        EXPECT_TRUE(x >= 0 && x < kGiDebugViewW && y >= 0 && y < kGiDebugViewH)
            << "probe " << p << " off screen";
        out.atProbe.push_back({radiance.at(x, y, 0), radiance.at(x, y, 1), radiance.at(x, y, 2)});
    }
    return out;
}

class GiDebugViewTest : public GlTest {};

// Probe p = i + 2 (k + 2 j): coordinates as in probeCoords. Sparse: probe 0 has no sphere.
void expectIrradianceSpheres(bool sparse) {
    const SphereCheck c = renderSpheres(render::GiDebugView::ProbesIrradiance, sparse);
    const probes::ProbeVolume v = syntheticVolume("air", {}, glm::vec3(0.3f), glm::ivec3(2));
    float maxRel = 0;
    for (size_t p = sparse ? 1 : 0; p < c.atProbe.size(); ++p) {
        const glm::vec3 expected = probeIrradiance(v.probeCoords(int(p))) / float(M_PI);
        for (int k = 0; k < 3; ++k) {
            maxRel = std::max(maxRel, std::abs(c.atProbe[p][k] - expected[k]) / expected[k]);
            EXPECT_NEAR(c.atProbe[p][k], expected[k], 2e-3f * expected[k] + 1e-3f) << p;
        }
    }
    std::printf("[ probe spheres ] %s: %zu spheres at their probes: radiance vs E / pi max rel "
                "%.3g (RGBA16F radiance)\n",
                sparse ? "sparse" : "dense", c.atProbe.size() - (sparse ? 1 : 0), double(maxRel));
}

TEST_F(GiDebugViewTest, IrradianceSpheresShowTheProbesIrradiance) {
    expectIrradianceSpheres(false);
}

TEST_F(GiDebugViewTest, SparseSpheresFindTheirPackedTiles) {
    expectIrradianceSpheres(true);
}

TEST_F(GiDebugViewTest, VisibilitySpheresAreBlackWhenInvalid) {
    const SphereCheck c = renderSpheres(render::GiDebugView::ProbesVisibility);
    for (size_t p = 0; p < c.atProbe.size(); ++p) {
        // Open visibility (mean distance 1) shows as the view's full brightness.
        const float expected = p == 0 ? 0.0f : 0.5f / c.exposure;
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(c.atProbe[p][k], expected, 2e-3f) << "probe " << p;
    }
}

// gi_only: the lighting outputs albedo / pi x indirect irradiance, i.e. the frame without the
// sun (rooms has no other light and no emission).
TEST_F(GiDebugViewTest, GiOnlyIsTheFrameWithoutDirectLight) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba16f);
    auto render = [&](bool sun, render::GiDebugView view) {
        scene::Scene s = giTestScene();
        s.sun.enabled = sun;
        render::GiOptions gi;
        gi.probes = &set;
        gi.debugView = view;
        render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
        r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 160, 90));
        return r.readRadiance();
    };
    const image::ImageF giOnly = render(true, render::GiDebugView::GiOnly);
    const image::ImageF noSun = render(false, render::GiDebugView::None);
    const image::ImageF full = render(true, render::GiDebugView::None);
    ASSERT_EQ(giOnly.pixels.size(), noSun.pixels.size());
    int surface = 0, differsFromFull = 0;
    for (size_t i = 0; i < giOnly.pixels.size(); i += 4) {
        if (noSun.pixels[i] == giTestScene().sky.radiance.x) continue; // sky: radiance as is
        ++surface;
        for (size_t c = 0; c < 3; ++c)
            ASSERT_EQ(giOnly.pixels[i + c], noSun.pixels[i + c]) << "pixel " << i / 4;
        differsFromFull += giOnly.pixels[i] < full.pixels[i] * 0.9f;
    }
    EXPECT_GT(surface, 160 * 90 / 2);
    EXPECT_GT(differsFromFull, surface / 100) << "the sun patch must be gone";
}

} // namespace
} // namespace pb::test
