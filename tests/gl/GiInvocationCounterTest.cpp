// The GI pass's invocation counter (GiApplyPass::setCountPixels on an ES 3.1 context:
// common_gi_invocations.glsl) on the three nested volumes (GiNestedVolumes.h): what the device
// shaded per volume, beside what each volume wrote (the "evaluated" attachment).
//   naive:   each volume's full-screen apply runs once per GI texel, whatever it evaluates;
//   stencil: the apply's early stencil test keeps taken texels out of the shader, so no
//            volume's apply runs on a texel a smaller volume has marked; only the discarding
//            mark draws (late-tested) and the apply's own discards (sky, the box's margin
//            outside the influence) run without evaluating. With the eye inside a box the
//            raster decides the influence: apply invocations = evaluated pixels.
// With the counter's own side effect deciding the tests (no early_fragment_tests) the rejected
// texels are shaded too: the measurement the counter's variant choice rests on.
#include "gl/GiNestedVolumes.h"
#include "gl/GlTestFixture.h"

#include <cstdio>

namespace pb::test {
namespace {

constexpr int kGiInvocationCounterW = 160, kGiInvocationCounterH = 90;

render::GiApplyPass* applyPass(render::FrameRenderer& r) {
    return r.giApplyPass();
}

// The texels of the rectangle a volume's draws were scissored to (GiVolumeRaster::screenRect).
std::int64_t rectTexels(const render::GiVolumeStats& v) {
    return std::int64_t(v.screenRect[2] - v.screenRect[0]) * (v.screenRect[3] - v.screenRect[1]);
}

render::GiPassStats renderCounted(const NestedCamera& cam, const std::string& multiVolume,
                                  const std::string& volumeLod = "", bool lateTests = false,
                                  const std::string& dynamic = "") {
    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &nestedVolumeProbes();
    gi.profile.applyOverride("gi.multi_volume=" + multiVolume);
    if (!volumeLod.empty()) gi.profile.applyOverride("gi.volume_lod=" + volumeLod);
    if (!dynamic.empty()) gi.profile.applyOverride("gi.dynamic=" + dynamic);
    // Build every pass: the test scene has no dynamic objects, and gi.dynamic=sh would
    // otherwise fall back to per_pixel.
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi, render::FrameBuild{false});
    applyPass(r)->setCountPixels(true);
    applyPass(r)->setCountInvocationsWithLateTests(lateTests);
    r.render(render::makeRenderView(cam.view, s.worldBounds(), kGiInvocationCounterW,
                                    kGiInvocationCounterH));
    return applyPass(r)->stats();
}

void print(const char* what, const NestedCamera& cam, const render::GiPassStats& s) {
    std::printf("[ invocations ] %s %s:", what, cam.name);
    for (const auto& v : s.volumes)
        std::printf(" %s evaluated %lld apply %lld mark %lld%s;", v.name.c_str(),
                    static_cast<long long>(v.evaluatedPixels),
                    static_cast<long long>(v.applyInvocations),
                    static_cast<long long>(v.markInvocations), v.culled ? " (culled)" : "");
    std::printf("\n");
}

class GiInvocationCounterTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        // Every context this suite runs on (llvmpipe ES 3.2) has atomic counters; where one
        // has not, the stats say why and these checks do not apply.
        const render::GiPassStats s = renderCounted(nestedCameras()[0], "naive");
        if (!s.invocationsCounted) GTEST_SKIP() << s.invocationsNote;
    }
};

TEST_F(GiInvocationCounterTest, NaiveRunsEveryVolumeOnEveryTexel) {
    int disagreeing = 0;
    for (const NestedCamera& cam : nestedCameras()) {
        SCOPED_TRACE(cam.name);
        const render::GiPassStats s = renderCounted(cam, "naive");
        print("naive", cam, s);
        ASSERT_TRUE(s.invocationsCounted);
        bool disagree = false;
        for (const auto& v : s.volumes) {
            if (v.culled) continue;
            // A full-screen triangle with no depth or stencil test, scissored to the box's
            // rectangle: one invocation per texel of the rectangle.
            EXPECT_EQ(v.applyInvocations, rectTexels(v)) << v.name;
            EXPECT_GE(v.applyInvocations, v.evaluatedPixels) << v.name;
            EXPECT_EQ(v.markInvocations, 0) << v.name;
            disagree = disagree || v.applyInvocations != v.evaluatedPixels;
        }
        // The stats flag exactly the frames where some volume shaded texels it did not
        // evaluate.
        EXPECT_EQ(s.invocationsDisagree(), disagree);
        disagreeing += disagree;
    }
    // Three of the views show surfaces outside the inner volumes: naive wastes work there.
    EXPECT_GE(disagreeing, 3);
}

TEST_F(GiInvocationCounterTest, StencilKeepsTakenTexelsOutOfTheApply) {
    // gi.dynamic=sh: the apply's dynamic-pixel early-out discards, so a raster-decided volume
    // keeps a separate (empty-shader) mark draw; otherwise its apply marks.
    for (const char* dynamic : {"per_pixel", "sh"})
        for (const NestedCamera& cam : nestedCameras()) {
            SCOPED_TRACE(std::string(cam.name) + " gi.dynamic=" + dynamic);
            const bool dynamicSh = std::string(dynamic) == "sh";
            const render::GiPassStats s = renderCounted(cam, "stencil", "", false, dynamic);
            print("stencil", cam, s);
            ASSERT_TRUE(s.invocationsCounted);
            EXPECT_TRUE(s.invocationsEarlyTests);
            std::int64_t taken = 0; // texels marked by the volumes drawn so far
            int rasterDecided = 0;
            for (const auto& v : s.volumes) {
                if (v.culled) continue;
                EXPECT_GE(v.applyInvocations, v.evaluatedPixels) << v.name;
                // The stencil test ran before the shader: at most the untaken texels reach it.
                EXPECT_LE(v.applyInvocations,
                          std::int64_t(kGiInvocationCounterW) * kGiInvocationCounterH - taken)
                    << v.name;
                // The mark evaluates the same influence test as the apply: it runs on at least the
                // texels it marks, and those are the ones the apply evaluated.
                if (v.fillPass && !v.markInApply) {
                    EXPECT_GE(v.markInvocations, v.evaluatedPixels) << v.name;
                } else {
                    // No mark draw: the last volume, or an apply that sets 'taken' itself.
                    EXPECT_EQ(v.markInvocations, 0) << v.name;
                }
                // Eye inside the box: the back faces' depth test alone selects the surfaces inside
                // it, so the apply discards nothing and the device shades exactly what it
                // evaluates.
                if (v.rasterInfluence) {
                    ++rasterDecided;
                    if (!dynamicSh) {
                        EXPECT_EQ(v.applyInvocations, v.evaluatedPixels) << v.name;
                    }
                    // The first volume drawn: nothing is taken yet, the mark runs early on exactly
                    // the pixels the apply evaluated.
                    EXPECT_EQ(v.markInApply, v.fillPass && !dynamicSh) << v.name;
                    if (taken == 0 && v.fillPass && !v.markInApply) {
                        EXPECT_EQ(v.markInvocations, v.evaluatedPixels) << v.name;
                    }
                }
                taken += v.evaluatedPixels;
            }
            // The cameras inside a volume exercise the raster-decided draws.
            if (std::string(cam.inside).empty()) {
                EXPECT_EQ(rasterDecided, 0);
            } else {
                EXPECT_GT(rasterDecided, 0);
            }
        }
}

// What the counter does to the tests when it alone decides (no early_fragment_tests): on
// llvmpipe every fragment of a rejected draw runs the shader. Either way the pixels evaluated
// (and the image) are the same; only the count of shaded fragments grows.
TEST_F(GiInvocationCounterTest, TheCounterWithoutEarlyTestsCountsRejectedFragments) {
    const NestedCamera cam = nestedCameras()[2]; // inside the inner volume
    const render::GiPassStats early = renderCounted(cam, "stencil");
    const render::GiPassStats late = renderCounted(cam, "stencil", "", true);
    print("stencil early", cam, early);
    print("stencil late", cam, late);
    EXPECT_FALSE(late.invocationsEarlyTests);
    ASSERT_EQ(early.volumes.size(), late.volumes.size());
    std::int64_t extra = 0;
    for (size_t i = 0; i < early.volumes.size(); ++i) {
        EXPECT_EQ(early.volumes[i].evaluatedPixels, late.volumes[i].evaluatedPixels);
        EXPECT_GE(late.volumes[i].applyInvocations, early.volumes[i].applyInvocations);
        // The discarding mark is late-tested either way; the raster mark (no discard) gets its
        // early tests in production, so only its count may differ.
        if (!early.volumes[i].rasterInfluence) {
            EXPECT_EQ(late.volumes[i].markInvocations, early.volumes[i].markInvocations);
        } else {
            EXPECT_GE(late.volumes[i].markInvocations, early.volumes[i].markInvocations);
        }
        extra += late.volumes[i].applyInvocations - early.volumes[i].applyInvocations;
    }
    std::printf("[ invocations ] late tests shade %lld more apply fragments\n",
                static_cast<long long>(extra));
}

// Wired: the counts follow the draws. Omitting the inner volume removes its draw; in naive
// every drawn volume costs one invocation per texel of its rectangle.
TEST_F(GiInvocationCounterTest, OmittingAVolumeRemovesItsInvocations) {
    const NestedCamera cam = nestedCameras()[1]; // inside the middle volume
    const render::GiPassStats all = renderCounted(cam, "naive");
    const render::GiPassStats omitted = renderCounted(cam, "naive", "omit:sun_patch");
    ASSERT_EQ(all.volumes.size(), 3u);
    ASSERT_EQ(omitted.volumes.size(), 2u);
    EXPECT_GT(omitted.totalApplyInvocations(), 0);
    EXPECT_EQ(all.volumes.back().name, "sun_patch") << "naive: smallest drawn last";
    EXPECT_EQ(all.totalApplyInvocations() - omitted.totalApplyInvocations(),
              rectTexels(all.volumes.back()));
    const render::GiPassStats stencilAll = renderCounted(cam, "stencil");
    const render::GiPassStats stencilOmitted = renderCounted(cam, "stencil", "omit:sun_patch");
    EXPECT_GT(stencilOmitted.totalApplyInvocations(), 0);
    EXPECT_NE(stencilAll.totalApplyInvocations() + stencilAll.totalMarkInvocations(),
              stencilOmitted.totalApplyInvocations() + stencilOmitted.totalMarkInvocations());
}

} // namespace
} // namespace pb::test
