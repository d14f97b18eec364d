// The cost model's counters on an analytic case: a floor seen from above, a root volume over
// all of it and a child over half (x > 0). Every count follows from the pass structure:
// one draw per volume, every fragment reads depth, pixels inside a volume read the normal and
// 8 probes x 3 fetches, the child wins its half. Same inputs give byte-identical JSON.
#include "unit/OpenProbeSets.h"
#include "unit/ProbeTestScenes.h"

#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "profile/GiVolumeLod.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

probes::ProbeVolume box(const std::string& name, glm::vec3 lo, glm::vec3 hi,
                        const std::string& parent = "") {
    probes::ProbeVolume v;
    v.name = name;
    v.center = 0.5f * (lo + hi);
    v.halfExtents = 0.5f * (hi - lo);
    v.counts = glm::ivec3(2);
    v.parent = parent;
    return v;
}

probes::ProbeSet setOf(std::vector<probes::ProbeVolume> vols) {
    return test::openProbeSet(vols);
}

scene::Scene floorScene() {
    scene::Scene s = emptyScene();
    int m = addMaterial(s, glm::vec3(0.5f));
    scene::Primitive p;
    p.material = m;
    addQuad(p, {-10, 0, -10}, {20, 0, 0}, {0, 0, 20}, {0, 1, 0});
    addInstance(s, std::move(p));
    return s;
}

scene::View downView() {
    scene::View v;
    v.name = "down";
    v.position = {0, 2, 0};
    v.target = {0, 0, 0};
    v.fovYDegrees = 60;
    return v;
}

costmodel::CostReport runOn(const probes::ProbeSet& set, const costmodel::CostModelOptions& o) {
    const scene::Scene s = floorScene();
    const views::CoverageTester tester(s, set);
    return costmodel::runCostModel(tester, downView(), o);
}

costmodel::CostModelOptions small() {
    costmodel::CostModelOptions o;
    o.width = 64;
    o.height = 36;
    o.caches = {costmodel::cachePresetFor("handheld"), costmodel::cachePresetFor("pc-high")};
    return o;
}

} // namespace

TEST(CostModelCounters, NestedVolumesOnAFloorGiveExactCounts) {
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10}),
                                        box("child", {0, -1, -10}, {10, 1, 10}, "root")});
    const costmodel::CostReport r = runOn(set, small());
    const costmodel::GiPassCounters& c = r.counters;
    const std::uint64_t pixels = 64 * 36;
    EXPECT_EQ(c.targetPixels, pixels);
    EXPECT_EQ(c.giPixels, pixels);
    ASSERT_EQ(c.volumes.size(), 2u);
    EXPECT_EQ(c.volumes[0].name, "root"); // the larger box draws first
    EXPECT_EQ(c.volumes[1].name, "child");
    EXPECT_EQ(c.volumes[0].evaluated, pixels);
    EXPECT_EQ(c.volumes[1].evaluated, pixels / 2); // pixel centres never lie on x = 0
    EXPECT_EQ(c.volumes[1].outsideSkipped, pixels / 2);
    EXPECT_EQ(c.volumes[1].won, pixels / 2);
    EXPECT_EQ(c.volumes[0].won, pixels / 2);
    const std::uint64_t lookups = pixels + pixels / 2;
    for (const costmodel::VolumeCounters& v : c.volumes) {
        EXPECT_EQ(v.fragments, pixels);
        EXPECT_EQ(v.skySkipped, 0u);
        EXPECT_EQ(v.fadedOut, 0u);
        EXPECT_EQ(v.depthFetches, pixels);
        EXPECT_EQ(v.normalFetches, v.evaluated);
        EXPECT_EQ(v.stateFetches, 8 * v.evaluated); // 2x2x2 grid: all 8 probes, all valid
        EXPECT_EQ(v.visibilityFetches, 8 * v.evaluated);
        EXPECT_EQ(v.irradianceFetches, 8 * v.evaluated);
    }
    EXPECT_EQ(c.gbufferFetches, 2 * pixels + lookups); // depth per draw, normal per lookup
    EXPECT_EQ(c.probeFetches, 24 * lookups);
    EXPECT_DOUBLE_EQ(c.fetchesPerGiPixel, double(c.gbufferFetches + c.probeFetches) / pixels);
    EXPECT_EQ(c.maxFetchesPerLookup, 26);
    EXPECT_EQ(c.drawCalls, 2);
    EXPECT_EQ(c.textureBinds, 5 + 2 * 3);
    EXPECT_EQ(c.renderTargetBytesWritten, lookups * 8); // rgba16f
    EXPECT_EQ(c.clearBytes, pixels * 8);
    EXPECT_EQ(c.gpuProbeBytes, profile::gpuVolumeBytes(set.volumes[0], set.format()) +
                                   profile::gpuVolumeBytes(set.volumes[1], set.format()));
    // Raw footprint: 16 B state + 4 visibility texels x 4 B + 4 irradiance texels x 8 B.
    EXPECT_EQ(c.probeFootprintBytes, lookups * 8 * (16 + 16 + 32));
    ASSERT_EQ(r.results.size(), 4u * 2u);
    for (const costmodel::CacheResult& res : r.results) {
        EXPECT_GT(res.probeLines, 0u);
        EXPECT_LE(res.probeHits, res.probeLines);
        EXPECT_GE(res.gbufferLines, c.gbufferFetches / 16); // at most 16 texels per line
    }
}

TEST(CostModelCounters, ResolutionTargetFormatAndVolumeLodChangeTheCounts) {
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10}),
                                        box("child", {0, -1, -10}, {10, 1, 10}, "root")});
    costmodel::CostModelOptions o = small();
    o.profile.set("gi.resolution", "half");
    o.profile.set("gi.target_format", "r11g11b10f");
    o.profile.set("gi.volume_lod", "omit:child");
    const costmodel::GiPassCounters c = runOn(set, o).counters;
    EXPECT_EQ(c.targetWidth, 32);
    EXPECT_EQ(c.targetHeight, 18);
    EXPECT_EQ(c.giPixels, 32u * 18u);
    EXPECT_EQ(c.drawCalls, 1);
    EXPECT_EQ(c.probeFetches, 24u * 32u * 18u);
    EXPECT_EQ(c.renderTargetBytesWritten, 32u * 18u * 4u);
    EXPECT_EQ(c.gpuProbeBytes, profile::gpuVolumeBytes(set.volumes[0], set.format()));
}

TEST(CostModelCounters, SameInputsGiveIdenticalJson) {
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10}),
                                        box("child", {0, -1, -10}, {10, 1, 10}, "root")});
    const std::string a = costmodel::reportJson(runOn(set, small())).dump();
    const std::string b = costmodel::reportJson(runOn(set, small())).dump();
    EXPECT_EQ(a, b);
    EXPECT_NE(a.find("\"probe_hit_rate\""), std::string::npos);
}

TEST(CostModelCounters, SkyPixelsReadOnlyDepth) {
    // Looking at the horizon: the upper half sees sky.
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10})});
    const scene::Scene s = floorScene();
    const views::CoverageTester tester(s, set);
    scene::View v = downView();
    v.position = {0, 0.5f, 0};
    v.target = {0, 0.5f, -1};
    const costmodel::GiPassCounters c = costmodel::runCostModel(tester, v, small()).counters;
    ASSERT_EQ(c.volumes.size(), 1u);
    const costmodel::VolumeCounters& vc = c.volumes[0];
    EXPECT_GT(vc.skySkipped, 0u);
    EXPECT_EQ(vc.skySkipped + vc.outsideSkipped + vc.evaluated, vc.fragments);
    EXPECT_EQ(c.giPixels, vc.evaluated);
    EXPECT_EQ(c.gbufferFetches, vc.fragments + vc.evaluated);
}

TEST(CostModelCounters, BadOptionsAreErrors) {
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10})});
    costmodel::CostModelOptions o = small();
    o.caches = {{"bad", 1000, 64, 4, ""}};
    EXPECT_THROW(runOn(set, o), Error);
    o = small();
    o.scenario = 3;
    EXPECT_THROW(runOn(set, o), Error);
}

// The apply reads the GBuffer flags of every non-sky fragment (before the influence test) when
// it needs them: gi.dynamic=sh always (its early-out), per_pixel only in a scene with dynamic
// objects (GI_DYNAMIC_UNFADED: their pixels skip the behind-surface fade), never otherwise.
TEST(CostModelCounters, FlagsAreFetchedWhereTheApplyNeedsThem) {
    const probes::ProbeSet set = setOf({box("root", {-10, -1, -10}, {10, 1, 10})});
    scene::Scene withDynamic = floorScene();
    scene::Primitive quad;
    quad.material = 0;
    addQuad(quad, {20, 0, 20}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}); // out of view: counts only
    addInstance(withDynamic, std::move(quad));
    withDynamic.instances.back().dynamic = true;
    withDynamic.instances.back().nodeName = "ball";
    const scene::Scene plain = floorScene();
    const auto flags = [&](const scene::Scene& s, const char* dynamic) {
        costmodel::CostModelOptions o = small();
        o.profile.set("gi.dynamic", dynamic);
        const views::CoverageTester tester(s, set);
        const costmodel::VolumeCounters v =
            costmodel::runCostModel(tester, downView(), o).counters.volumes.at(0);
        EXPECT_EQ(v.fragments - v.skySkipped, 64u * 36u);
        return v.flagsFetches;
    };
    EXPECT_EQ(flags(plain, "per_pixel"), 0u);
    EXPECT_EQ(flags(withDynamic, "per_pixel"), 64u * 36u);
    EXPECT_EQ(flags(plain, "sh"), 64u * 36u);
    EXPECT_EQ(flags(withDynamic, "sh"), 64u * 36u);
}

} // namespace pb::test
