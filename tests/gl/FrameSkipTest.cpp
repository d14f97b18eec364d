// The frame builds only what the scene and profile need (frame/FrameSkips.h): no shadow pass
// without a shadow-casting light, no SH pass (nor its textures) without dynamic objects, no
// textures for omitted volumes, no GI passes in a frame whose view sees no volume - and every
// skip leaves the image bit for bit as the full build renders it (FrameBuild{false}). Also the
// GI memory estimate (frame/GiMemory.h) against what a frame really allocates.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"
#include "frame/GiMemory.h"
#include "passes/DynamicObjects.h"

#include <algorithm>

namespace pb::test {
namespace {

using FrameSkipTest = GlTest;

constexpr int kFrameSkipW = 96, kFrameSkipH = 54;

std::vector<std::string> passNames(const render::FrameRenderer& r) {
    std::vector<std::string> names;
    for (const auto& p : r.passes())
        names.push_back(p->name());
    return names;
}

bool hasPass(const render::FrameRenderer& r, const std::string& name) {
    const auto names = passNames(r);
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool skippedMentions(const render::FrameRenderer& r, const std::string& what) {
    for (const render::SkippedWork& w : r.skipped())
        if (render::skippedLine(w).find(what) != std::string::npos) return true;
    return false;
}

render::GiOptions frameSkipGi(const std::vector<std::string>& sets = {}) {
    render::GiOptions o;
    o.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    for (const auto& kv : sets)
        o.profile.applyOverride(kv);
    return o;
}

// Renders one frame of `view` (a scene view or a camera) lean and full; returns both renderers.
struct Pair {
    std::unique_ptr<render::FrameRenderer> lean, full;
};
Pair renderBoth(const scene::Scene& s, const scene::View& view, const render::GiOptions& o) {
    Pair p;
    p.lean = std::make_unique<render::FrameRenderer>(s, render::defaultFrameSettings(s), o);
    p.full = std::make_unique<render::FrameRenderer>(s, render::defaultFrameSettings(s), o,
                                                     render::FrameBuild{false});
    const render::RenderView rv =
        render::makeRenderView(view, s.worldBounds(), kFrameSkipW, kFrameSkipH);
    p.lean->render(rv);
    p.full->render(rv);
    return p;
}

void expectSameImage(const Pair& p) {
    EXPECT_EQ(p.lean->readRadiance().pixels, p.full->readRadiance().pixels);
    EXPECT_EQ(p.lean->readOutput().pixels, p.full->readOutput().pixels);
}

TEST_F(FrameSkipTest, NoShadowPassWithoutAShadowCastingLight) {
    const scene::Scene cornell = scene::makeBuiltinScene("cornell"); // sun off
    Pair off = renderBoth(cornell, cornell.views.front(), {});
    EXPECT_FALSE(hasPass(*off.lean, "shadow"));
    EXPECT_TRUE(hasPass(*off.full, "shadow"));
    EXPECT_TRUE(skippedMentions(*off.lean, "skipped pass shadow (no shadow map): the sun is off"));
    expectSameImage(off);

    // A sun of zero irradiance: the full build draws a real shadow map the lighting multiplies
    // by 0; the lean frame draws none and gets the same pixels.
    scene::Scene dark = scene::makeBuiltinScene("rooms");
    dark.sun.intensity = 0.0f;
    Pair zero = renderBoth(dark, *dark.findView("sunlit_room"), {});
    EXPECT_FALSE(hasPass(*zero.lean, "shadow"));
    EXPECT_TRUE(skippedMentions(*zero.lean, "zero irradiance"));
    expectSameImage(zero);

    const scene::Scene rooms = scene::makeBuiltinScene("rooms"); // sun on: the pass stays
    render::FrameRenderer sunny(rooms, render::defaultFrameSettings(rooms));
    EXPECT_TRUE(hasPass(sunny, "shadow"));
    EXPECT_FALSE(skippedMentions(sunny, "pass shadow"));
}

TEST_F(FrameSkipTest, NoShPassNorShTexturesWithoutDynamicObjects) {
    const scene::Scene& s = giTestScene(); // rooms: no dynamic object
    ASSERT_TRUE(render::findDynamicObjects(s).objects.empty());
    Pair p = renderBoth(s, *s.findView("sunlit_room"), frameSkipGi({"gi.dynamic=sh"}));
    EXPECT_FALSE(hasPass(*p.lean, "gi-dynamic-sh"));
    EXPECT_EQ(p.lean->giMemory().dynamicSh, 0u);
    EXPECT_TRUE(hasPass(*p.full, "gi-dynamic-sh"));
    EXPECT_GT(p.full->giMemory().dynamicSh, 0u);
    EXPECT_TRUE(skippedMentions(*p.lean, "skipped pass gi-dynamic-sh: gi.dynamic=sh but the "
                                         "scene has no dynamic objects"));
    expectSameImage(p);

    // With a dynamic object the pass is built.
    scene::Scene moving = s;
    for (auto& inst : moving.instances)
        inst.dynamic = inst.nodeName == "sofa";
    render::FrameRenderer withObject(moving, render::defaultFrameSettings(moving),
                                     frameSkipGi({"gi.dynamic=sh"}));
    EXPECT_TRUE(hasPass(withObject, "gi-dynamic-sh"));
    EXPECT_GT(withObject.giMemory().dynamicSh, 0u);
}

TEST_F(FrameSkipTest, OmittedVolumesHaveNoTexturesAndAreListed) {
    const scene::Scene& s = giTestScene();
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba16f);
    const std::string root = set.volumes[0].name;
    render::FrameRenderer all(s, render::defaultFrameSettings(s), frameSkipGi());
    render::FrameRenderer noChild(s, render::defaultFrameSettings(s),
                                  frameSkipGi({"gi.volume_lod=omit:child"}));
    render::FrameRenderer none(s, render::defaultFrameSettings(s),
                               frameSkipGi({"gi.volume_lod=omit:" + root}));
    EXPECT_EQ(all.gpuProbes()->volumes().size(), 2u);
    EXPECT_EQ(noChild.gpuProbes()->volumes().size(), 1u);
    EXPECT_LT(noChild.giMemory().probes, all.giMemory().probes);
    EXPECT_EQ(none.giMemory().probes, 0u);
    EXPECT_TRUE(skippedMentions(noChild, "skipped volume 'child'"));
    EXPECT_FALSE(skippedMentions(noChild, "volume '" + root + "'"));
    // The child goes with its parent, and says so.
    EXPECT_TRUE(skippedMentions(none, "skipped volume '" + root + "'"));
    EXPECT_TRUE(skippedMentions(none, "its parent '" + root + "' is left out"));
}

TEST_F(FrameSkipTest, AViewThatSeesNoVolumeRunsNoGiPassAndLooksTheSame) {
    const scene::Scene& s = giTestScene();
    // Above the house looking at the sky: every volume is behind the camera.
    const scene::View up = scene::parseCameraSpec("0,30,0,0,60,0.1,60");
    for (const char* res : {"gi.resolution=full", "gi.resolution=half"}) {
        SCOPED_TRACE(res);
        Pair p = renderBoth(s, up, frameSkipGi({res, "gi.upsample=temporal"}));
        EXPECT_TRUE(p.lean->giSkippedLastFrame());
        EXPECT_FALSE(p.full->giSkippedLastFrame());
        expectSameImage(p);
        // Resources stay: the next frame that sees a volume uses them.
        EXPECT_GT(p.lean->giMemory().probes, 0u);
    }
    // Timed sections: only the passes that ran.
    render::FrameRenderer r(s, render::defaultFrameSettings(s), frameSkipGi());
    struct Names : render::FrameTimer {
        std::vector<std::string> names;
        void begin(const char* n) override { names.push_back(n); }
        void end(const char*) override {}
    } timer;
    r.render(render::makeRenderView(up, s.worldBounds(), kFrameSkipW, kFrameSkipH), &timer);
    EXPECT_EQ(std::count(timer.names.begin(), timer.names.end(), "gi-apply"), 0);
    // Looking into the house again: the GI runs.
    const render::RenderView in = render::makeRenderView(*s.findView("sunlit_room"),
                                                         s.worldBounds(), kFrameSkipW, kFrameSkipH);
    r.render(in);
    EXPECT_FALSE(r.giSkippedLastFrame());
    render::FrameRenderer reference(s, render::defaultFrameSettings(s), frameSkipGi(),
                                    render::FrameBuild{false});
    reference.render(in);
    EXPECT_EQ(r.readRadiance().pixels, reference.readRadiance().pixels);
}

TEST_F(FrameSkipTest, GiMemoryEstimateMatchesWhatAFrameAllocates) {
    scene::Scene s = giTestScene();
    for (auto& inst : s.instances)
        inst.dynamic = inst.nodeName == "sofa" || inst.nodeName == "pillar";
    const int objects = int(render::findDynamicObjects(s).objects.size());
    ASSERT_EQ(objects, 2);
    const std::vector<std::vector<std::string>> variants = {
        {},
        {"gi.resolution=half", "gi.target_format=r11g11b10f"},
        {"gi.resolution=quarter", "gi.upsample=temporal", "gi.multi_volume=stencil"},
        {"gi.resolution=half", "gi.upsample=bilateral", "gi.target_format=rgba32f"},
        {"gi.dynamic=sh", "gi.volume_lod=omit:child"},
    };
    for (const auto& sets : variants) {
        render::GiOptions o = frameSkipGi(sets);
        SCOPED_TRACE(o.profile.valuesJson().dump());
        render::FrameRenderer r(s, render::defaultFrameSettings(s), o);
        r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 101, 57));
        const render::GiMemory got = r.giMemory();
        const render::GiMemory want =
            render::estimateGiMemory(o.profile, *o.probes, 101, 57, objects);
        EXPECT_EQ(got.probes, want.probes);
        EXPECT_EQ(got.evaluation, want.evaluation);
        EXPECT_EQ(got.upsample, want.upsample);
        EXPECT_EQ(got.dynamicSh, want.dynamicSh);
        EXPECT_GT(got.total(), 0u);
    }
}

} // namespace
} // namespace pb::test
