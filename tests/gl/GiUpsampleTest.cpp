// gi.upsample (passes/GiUpsamplePass): the temporal history converges to full-resolution GI on
// a still camera, a cut (explicit or detected) starts over from the bilateral result, dynamic
// pixels never use the history, and the bilateral filter never blends across a depth step
// beyond its tolerance (a hand-made GBuffer).
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"
#include "frame/Readback.h"
#include "gl/ProgramCache.h"
#include "passes/GiApplyPass.h"
#include "passes/GiUpsamplePass.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace pb::test {
namespace {

constexpr int kGiUpsampleW = 160,
              kGiUpsampleH = 88; // divisible by 4: every pixel gets exact samples

render::RenderView viewOf(const scene::Scene& s, const char* name) {
    return render::makeRenderView(*s.findView(name), s.worldBounds(), kGiUpsampleW, kGiUpsampleH);
}

std::unique_ptr<render::FrameRenderer> renderer(const scene::Scene& s,
                                                const std::vector<std::string>& sets) {
    render::GiOptions gi;
    gi.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    for (const auto& kv : sets)
        gi.profile.applyOverride(kv);
    return std::make_unique<render::FrameRenderer>(s, render::defaultFrameSettings(s), gi);
}

// The full-resolution GI the lighting read last frame: the upsample pass's output, or at full
// resolution the apply pass's target.
image::ImageF giImage(const render::FrameRenderer& r) {
    if (const render::GiUpsamplePass* up = r.giUpsample()) return render::readFloat(*up->output());
    for (const auto& p : r.passes())
        if (auto* apply = dynamic_cast<const render::GiApplyPass*>(p.get()))
            return render::readFloat(*apply->target());
    return {};
}

// Mean and max of |a - b| over RGB, relative to the mean of |b|.
struct Diff {
    double mean = 0, max = 0;
};

Diff relativeDiff(const image::ImageF& a, const image::ImageF& b,
                  const std::vector<bool>* only = {}) {
    double sum = 0, ref = 0, mx = 0;
    size_t n = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3 || (only && !(*only)[i / 4])) continue;
        const double d = std::abs(double(a.pixels[i]) - b.pixels[i]);
        sum += d;
        mx = std::max(mx, d);
        ref += std::abs(b.pixels[i]);
        ++n;
    }
    const double scale = std::max(ref / double(std::max<size_t>(n, 1)), 1e-12);
    return {sum / double(std::max<size_t>(n, 1)) / scale, mx / scale};
}

class GiUpsampleTest : public GlTest, public ::testing::WithParamInterface<const char*> {};

// Stated accuracy: once every pixel of a footprint was sampled (4 frames at half, 16 at
// quarter), no pixel of the temporal result differs from full-resolution GI by more than 1e-3
// of the mean GI (on llvmpipe it is bit-identical: each history pixel holds the same shader's
// result for the same GBuffer pixel), while the first frame (bilateral) is far off.
TEST_P(GiUpsampleTest, TemporalConvergesToFullResolutionOnAStillCamera) {
    const scene::Scene& s = giTestScene();
    const render::RenderView view = viewOf(s, "sunlit_room");
    auto full = renderer(s, {});
    full->render(view);
    const image::ImageF expected = giImage(*full);
    auto temporal =
        renderer(s, {std::string("gi.resolution=") + GetParam(), "gi.upsample=temporal"});
    const int div = profile::resolutionDivisor(std::string(GetParam()) == "half"
                                                   ? profile::GiResolution::Half
                                                   : profile::GiResolution::Quarter);
    Diff first, converged;
    for (int frame = 0; frame <= div * div; ++frame) {
        temporal->render(view);
        const Diff d = relativeDiff(giImage(*temporal), expected);
        if (frame == 0) first = d;
        converged = d;
        EXPECT_EQ(temporal->giUpsample()->historyUsed(), frame > 0);
    }
    std::printf("[ temporal %s ] vs full: first frame mean %.3g max %.3g; after %d frames mean "
                "%.3g max %.3g\n",
                GetParam(), first.mean, first.max, div * div, converged.mean, converged.max);
    EXPECT_LE(converged.mean, 1e-3);
    EXPECT_LE(converged.max, 1e-3);
    EXPECT_GT(first.mean, 10.0 * converged.mean) << "the first frame has no history to use";
}

INSTANTIATE_TEST_SUITE_P(Resolutions, GiUpsampleTest, ::testing::Values("half", "quarter"),
                         [](const auto& info) { return std::string(info.param); });

class GiUpsampleHistoryTest : public GlTest {};

// The shader's reprojection (a still camera skips it): after converging, the camera turns by
// about two pixels. Reprojected correctly, the history still holds full-resolution detail and
// beats this frame's bilateral reconstruction by far; a history two pixels off, or read at
// the wrong place, would not.
TEST_F(GiUpsampleHistoryTest, HistoryFollowsACameraTurn) {
    const scene::Scene& s = giTestScene();
    const scene::View start = *s.findView("sunlit_room");
    scene::View turned = start;
    const glm::vec3 look = start.target - start.position;
    const float angle = glm::radians(2.0f * start.fovYDegrees / float(kGiUpsampleH)); // ~2 pixels
    turned.target =
        start.position + glm::vec3(std::cos(angle) * look.x + std::sin(angle) * look.z, look.y,
                                   -std::sin(angle) * look.x + std::cos(angle) * look.z);
    const render::RenderView a =
        render::makeRenderView(start, s.worldBounds(), kGiUpsampleW, kGiUpsampleH);
    const render::RenderView b =
        render::makeRenderView(turned, s.worldBounds(), kGiUpsampleW, kGiUpsampleH);
    auto full = renderer(s, {});
    auto bilateral = renderer(s, {"gi.resolution=half", "gi.upsample=bilateral"});
    auto temporal = renderer(s, {"gi.resolution=half", "gi.upsample=temporal"});
    for (int i = 0; i < 4; ++i)
        temporal->render(a);
    temporal->render(b);
    ASSERT_TRUE(temporal->giUpsample()->historyUsed()) << "a small turn is no cut";
    full->render(b);
    bilateral->render(b);
    const image::ImageF expected = giImage(*full);
    const Diff t = relativeDiff(giImage(*temporal), expected);
    const Diff bl = relativeDiff(giImage(*bilateral), expected);
    std::printf("[ turn ] vs full after a 2-pixel turn: temporal mean %.3g, bilateral mean %.3g\n",
                t.mean, bl.mean);
    // Measured: 0.45x here; reading the history half a pixel off gives 0.88x, not
    // reprojecting 1.5x, a mirrored motion 2.3x.
    EXPECT_LT(t.mean, 0.6 * bl.mean);
}

TEST_F(GiUpsampleHistoryTest, ACutRestartsFromTheBilateralResult) {
    const scene::Scene& s = giTestScene();
    auto bilateral = renderer(s, {"gi.resolution=half", "gi.upsample=bilateral"});
    auto temporal = renderer(s, {"gi.resolution=half", "gi.upsample=temporal"});
    const render::RenderView a = viewOf(s, "sunlit_room"), b = viewOf(s, "doorway");
    bilateral->render(b);
    const image::ImageF expected = giImage(*bilateral);

    // Explicit reset: the application announces the cut.
    for (int i = 0; i < 3; ++i)
        temporal->render(a);
    temporal->resetGiHistory();
    temporal->render(b);
    EXPECT_FALSE(temporal->giUpsample()->historyUsed());
    image::ImageF got = giImage(*temporal);
    ASSERT_EQ(got.pixels.size(), expected.pixels.size());
    EXPECT_EQ(std::memcmp(got.pixels.data(), expected.pixels.data(), got.pixels.size() * 4), 0)
        << "first frame after an explicit cut differs from bilateral: mean "
        << relativeDiff(got, expected).mean;
    temporal->render(b);
    EXPECT_TRUE(temporal->giUpsample()->historyUsed()) << "the history resumes after the cut";

    // Detected: the camera jumps from one room to the other without a word.
    for (int i = 0; i < 3; ++i)
        temporal->render(a);
    temporal->render(b);
    EXPECT_FALSE(temporal->giUpsample()->historyUsed()) << "the jump is a cut by the rule";
    got = giImage(*temporal);
    EXPECT_EQ(std::memcmp(got.pixels.data(), expected.pixels.data(), got.pixels.size() * 4), 0)
        << "first frame after a detected cut differs from bilateral";
}

TEST_F(GiUpsampleHistoryTest, DynamicPixelsBypassTheHistory) {
    scene::SceneOptions opts;
    opts.dynamicNodes = {"table"};
    const scene::Scene s = scene::loadScene("rooms", opts);
    const render::RenderView view = viewOf(s, "sunlit_room");
    auto bilateral = renderer(s, {"gi.resolution=half", "gi.upsample=bilateral"});
    auto temporal = renderer(s, {"gi.resolution=half", "gi.upsample=temporal"});
    auto full = renderer(s, {});
    bilateral->render(view);
    full->render(view);
    // Frame 4 samples like frame 0 (the jitter period is 4), i.e. like bilateral.
    for (int i = 0; i < 5; ++i)
        temporal->render(view);
    const image::Image8 flags = render::readRgba8(temporal->targets()->gbuffer.channel(3));
    std::vector<bool> dynamic(size_t(kGiUpsampleW) * kGiUpsampleH),
        still(size_t(kGiUpsampleW) * kGiUpsampleH);
    int dynamicCount = 0;
    for (size_t p = 0; p < dynamic.size(); ++p) {
        dynamic[p] = (flags.pixels[p * 4] & render::kFlagDynamic) != 0;
        still[p] = !dynamic[p];
        dynamicCount += dynamic[p];
    }
    ASSERT_GT(dynamicCount, 200) << "the table must be in view";
    const image::ImageF got = giImage(*temporal);
    const Diff vsBilateral = relativeDiff(got, giImage(*bilateral), &dynamic);
    const Diff vsFullOnTable = relativeDiff(got, giImage(*full), &dynamic);
    const Diff vsFullElsewhere = relativeDiff(got, giImage(*full), &still);
    std::printf("[ dynamic ] table (%d px): vs bilateral %.3g, vs full %.3g; static vs full %.3g\n",
                dynamicCount, vsBilateral.max, vsFullOnTable.mean, vsFullElsewhere.mean);
    EXPECT_EQ(vsBilateral.max, 0.0) << "dynamic pixels are this frame's reconstruction";
    EXPECT_GT(vsFullOnTable.mean, 10.0 * vsFullElsewhere.mean)
        << "static pixels converged, the table's did not accumulate";
}

// The upsample shaders are not profile-define variants (gi.upsample picks the file), so
// GiVariantsTest does not see them: compile and link each on every headless backend here.
class GiUpsampleShadersTest : public GlBackendTest {};

TEST_P(GiUpsampleShadersTest, EveryModeCompilesAndLinks) {
    gl::ProgramCache programs;
    for (const char* frag :
         {"gi_upsample_bilinear.frag", "gi_upsample_bilateral.frag", "gi_upsample_temporal.frag"})
        EXPECT_NO_THROW(programs.get("fullscreen.vert", frag)) << frag;
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiUpsampleShadersTest);

} // namespace
} // namespace pb::test
