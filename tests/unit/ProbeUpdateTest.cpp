// Issue 20: the update engine's schedules, events and marking (renderer/respond).
#include "respond/ProbeUpdate.h"
#include "core/Error.h"
#include "probes/ProbeLayout.h"
#include "probes/bake/Baker.h"
#include "respond/BlendSchedule.h"
#include "respond/ResponseEvent.h"
#include "respond/ResponseMetrics.h"
#include "respond/SampleBakes.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace pb;
using namespace pb::respond;

namespace {

// Blends `updates` samples of a constant `input` into `start`, texel 0's red channel returned
// after each update.
std::vector<float> blendConstant(Schedule s, float start, float input, int updates,
                                 int firstIndex = 1) {
    std::vector<float> stored(3 * probes::kIrradianceInteriorTexels, start),
        fresh(3 * probes::kIrradianceInteriorTexels, input), out;
    for (int n = 0; n < updates; ++n) {
        blendTexels(s, {}, firstIndex + n, fresh.data(), stored.data(),
                    probes::kIrradianceInteriorTexels);
        out.push_back(stored[0]);
    }
    return out;
}

} // namespace

TEST(BlendSchedule, EveryScheduleConvergesToAConstantInput) {
    for (Schedule s : {Schedule::Hysteresis, Schedule::Rtxgi, Schedule::Hastened})
        for (float start : {0.0f, 5.0f}) {
            const std::vector<float> v = blendConstant(s, start, 1.5f, 600);
            EXPECT_NEAR(v.back(), 1.5f, 1.5e-3f) << scheduleName(s) << " from " << start;
        }
}

TEST(BlendSchedule, HysteresisFollowsItsClosedForm) {
    // A unit step down to 0: what is left after n updates is h^n.
    const ScheduleParams p;
    const std::vector<float> v = blendConstant(Schedule::Hysteresis, 1.0f, 0.0f, 200);
    for (int n : {1, 10, 50, 98, 151, 200})
        EXPECT_NEAR(v[std::size_t(n - 1)], hysteresisResidual(p, n), 1e-5 * n) << n;
    // The published arithmetic: ~98 updates to 5%, ~151 to 1%.
    EXPECT_GT(hysteresisResidual(p, 98), 0.05 * 0.98);
    EXPECT_LT(hysteresisResidual(p, 99), 0.05);
    EXPECT_LT(hysteresisResidual(p, 152), 0.01);
}

TEST(BlendSchedule, HastenedWeightsDescendFromTheMaximumToTheFloor) {
    const ScheduleParams p;
    EXPECT_FLOAT_EQ(hastenedWeight(1, p), 1.0f);
    EXPECT_FLOAT_EQ(hastenedWeight(4, p), 0.25f);
    EXPECT_FLOAT_EQ(hastenedWeight(1000, p), 1.0f / 32.0f);
    EXPECT_EQ(hastenedStart(0.0f, 2.0f, p), 1);
    EXPECT_EQ(hastenedStart(2.0f, 2.0f, p), p.hastenedMaxStart);
    EXPECT_EQ(hastenedStart(5.0f, 0.0f, p), 1); // global change
    // At the change the first sample replaces the old value: the step is gone at once.
    EXPECT_FLOAT_EQ(blendConstant(Schedule::Hastened, 4.0f, 1.0f, 1).back(), 1.0f);
    // Weights 1/i are the running mean: samples 1..n starting at index 1 average exactly.
    std::vector<float> stored(3 * probes::kIrradianceInteriorTexels, 9.0f);
    float sum = 0;
    for (int i = 1; i <= 5; ++i) {
        std::vector<float> fresh(3 * probes::kIrradianceInteriorTexels, float(i));
        sum += float(i);
        blendTexels(Schedule::Hastened, {}, i, fresh.data(), stored.data(),
                    probes::kIrradianceInteriorTexels);
    }
    EXPECT_NEAR(stored[0], sum / 5.0f, 1e-6f);
}

TEST(BlendSchedule, RtxgiDropsHysteresisOnALargeChange) {
    // A large step: RTXGI's rules respond faster than plain hysteresis.
    const auto rt = blendConstant(Schedule::Rtxgi, 4.0f, 0.5f, 20);
    const auto hy = blendConstant(Schedule::Hysteresis, 4.0f, 0.5f, 20);
    EXPECT_LT(std::fabs(rt.back() - 0.5f), std::fabs(hy.back() - 0.5f));
    // A small change (below both thresholds) blends like hysteresis (in the gamma-5 encoding,
    // which for a small change is the linear blend to first order).
    const auto rtSmall = blendConstant(Schedule::Rtxgi, 1.0f, 1.001f, 5);
    const auto hySmall = blendConstant(Schedule::Hysteresis, 1.0f, 1.001f, 5);
    EXPECT_NEAR(rtSmall.back(), hySmall.back(), 1e-5f);
}

TEST(BlendSchedule, ParsesScheduleLists) {
    EXPECT_EQ(parseSchedules("hastened,hysteresis", "--schedule").size(), 2u);
    EXPECT_THROW(parseSchedules("fast", "--schedule"), Error);
    EXPECT_THROW(parseSchedules("rtxgi,rtxgi", "--schedule"), Error);
}

TEST(ResponseEvent, ParsesEveryForm) {
    EXPECT_EQ(parseEvent("sun:off@10").kind, EventKind::SunOff);
    EXPECT_EQ(parseEvent("sun:off@10").frame, 10);
    const ResponseEvent m = parseEvent("light:lamp:move:1,2,3@4");
    EXPECT_EQ(m.kind, EventKind::LightMove);
    EXPECT_EQ(m.name, "lamp");
    EXPECT_EQ(m.value, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(parseEvent("light:lamp:scale:0.5@0").scale, 0.5f);
    EXPECT_EQ(parseEvent("node:table:remove@3").kind, EventKind::NodeRemove);
    EXPECT_EQ(parseEvent("node:table:insert:0,0,0@3").kind, EventKind::NodeInsert);
    for (const char* bad : {"sun:off", "sun:dim@1", "light:lamp@2", "light:lamp:move:1,2@3",
                            "sun:off@x", "sun:off@1.5", "moon:off@1", "light:a:scale:-1@0"})
        EXPECT_THROW(parseEvent(bad), Error) << bad;
}

namespace {

struct Fixture {
    World world;
    probes::ProbeSet set;
};

Fixture bakedCornellWithLamp() {
    Fixture f;
    f.world.scene = scene::loadScene("cornell");
    scene::Light lamp;
    lamp.name = "lamp";
    lamp.position = f.world.scene.worldBounds().center();
    lamp.intensity = 2.0f;
    f.world.scene.lights.push_back(lamp);
    probes::BakeRequest r;
    probes::ProbeVolume v;
    v.name = "v";
    v.center = f.world.scene.worldBounds().center();
    v.halfExtents = f.world.scene.worldBounds().size() * 0.45f;
    v.counts = {4, 3, 4};
    r.volumes = {v};
    r.scenarios = probes::resolveScenarios({}, {}, f.world.scene);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 1;
    r.settings.noiseTarget = 0.0f;
    r.settings.format = probes::StorageFormat::Rgba32f;
    f.world.scenario = r.scenarios[0];
    f.set = probes::bakeProbes(f.world.scene, r);
    return f;
}

void constantSample(const ProbeRef&, int, float* rgb) {
    for (int i = 0; i < 3 * probes::kIrradianceInteriorTexels; ++i)
        rgb[i] = 0.25f;
}

} // namespace

TEST(ResponseEvent, ChecksNamesAndFramesAgainstTheScene) {
    const Fixture f = bakedCornellWithLamp();
    EXPECT_NO_THROW(checkEvent(parseEvent("light:lamp:off@5"), f.world, 10));
    EXPECT_THROW(checkEvent(parseEvent("light:nolamp:off@5"), f.world, 10), Error);
    EXPECT_THROW(checkEvent(parseEvent("node:nothing:remove@5"), f.world, 10), Error);
    EXPECT_THROW(checkEvent(parseEvent("sun:off@10"), f.world, 10), Error);
}

TEST(ProbeUpdate, AnEventWithNoEffectChangesNothingBitForBit) {
    Fixture f = bakedCornellWithLamp();
    const auto before = f.set.irradiance[0][0].texels;
    const World initial = f.world;
    // A light scaled by 1 leaves the bake's inputs as they were: nothing is marked.
    World after = f.world;
    const Change c = applyEvent(parseEvent("light:lamp:scale:1@0"), after, initial);
    ASSERT_FALSE(bakeInputsDiffer(initial, after, f.set));
    ProbeUpdater u(f.set, 0, Schedule::Hastened);
    EXPECT_EQ(u.mark(c, 1.0f, bakeInputsDiffer(initial, after, f.set)), 0u);
    EXPECT_TRUE(u.step(0, constantSample).empty());
    // A local change far outside every probe's radius marks nothing either.
    Change far;
    far.points = {glm::vec3(1000.0f)};
    EXPECT_EQ(u.mark(far, 1.0f), 0u);
    EXPECT_TRUE(u.step(0, constantSample).empty());
    EXPECT_EQ(0, std::memcmp(before.data(), f.set.irradiance[0][0].texels.data(),
                             before.size() * sizeof(float)));
}

TEST(ProbeUpdate, MarksByRadiusAndConvergesMarkedProbesOnly) {
    Fixture f = bakedCornellWithLamp();
    const probes::ProbeSet original = f.set;
    ProbeUpdater u(f.set, 0, Schedule::Hysteresis);
    Change c;
    const glm::vec3 at = probeWorldPosition(f.set, {0, 0});
    c.points = {at};
    const float radius = f.set.volumes[0].minCellSize() * 1.01f;
    const std::size_t marked = u.mark(c, radius);
    ASSERT_GT(marked, 0u);
    ASSERT_LT(marked, std::size_t(f.set.volumes[0].probeCount()));
    // Budget 1: one probe per frame, nearest first.
    const auto first = u.step(1, constantSample);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0], (ProbeRef{0, 0}));
    for (int n = 0; n < 400; ++n)
        u.step(0, constantSample);
    for (int p = 0; p < f.set.volumes[0].probeCount(); ++p) {
        const glm::ivec3 g = f.set.volumes[0].probeCoords(p);
        const float* t = f.set.irradiance[0][0].at(g.x * probes::kIrradianceTile + 3,
                                                   g.z * probes::kIrradianceTile + 3, g.y);
        const float* o = original.irradiance[0][0].at(g.x * probes::kIrradianceTile + 3,
                                                      g.z * probes::kIrradianceTile + 3, g.y);
        const bool near = glm::length(probeWorldPosition(f.set, {0, p}) - at) <= radius &&
                          f.set.states[0][std::size_t(p)].valid;
        if (near)
            EXPECT_NEAR(t[0], 0.25f, 1e-4f) << p;
        else
            EXPECT_EQ(t[0], o[0]) << p;
    }
}

TEST(ResponseMetrics, SettleFrameOvershootFlickerAndDrift) {
    EXPECT_EQ(settleFrame({1.0, 0.5, 0.04, 0.06, 0.03, 0.02}, 0.05), 4);
    EXPECT_EQ(settleFrame({1.0, 0.5}, 0.05), -1);
    // Reference 1, start 2: a frame at 0.5 went half a step past it.
    const LumaImage ref{1.0f, 1.0f};
    std::vector<LumaImage> frames{{2.0f, 2.0f}, {0.5f, 0.5f}, {1.0f, 1.0f}};
    EXPECT_NEAR(overshoot(frames, ref), 0.5, 1e-9);
    EXPECT_NEAR(meanAbsError(frames[0], ref), 1.0, 1e-9);
    // Constant frames do not flicker; alternating 1 and 3 has CV 0.5.
    EXPECT_EQ(flicker({{1.0f}, {1.0f}, {1.0f}}, 30), 0.0);
    EXPECT_NEAR(flicker({{1.0f}, {3.0f}, {1.0f}, {3.0f}}, 30), 0.5, 1e-9);
    // Pixel 1 lies beyond the change's reach; it drifts 10% while pixel 0 follows the change.
    const FarDrift d = farDrift({{3.0f, 2.0f}, {1.0f, 2.2f}, {1.0f, 2.1f}}, {false, true});
    EXPECT_EQ(d.pixels, 1u);
    EXPECT_NEAR(d.drift, 0.1, 1e-6);
    EXPECT_EQ(farDrift({{3.0f}, {1.0f}}, {false}).pixels, 0u);
}

TEST(ResponseEvent, ReadsATomlTimeline) {
    const std::filesystem::path dir =
        std::filesystem::path(PB_TEST_OUTPUT_DIR) / "respond_timeline";
    std::filesystem::create_directories(dir);
    const auto good = dir / "good.toml";
    std::ofstream(good)
        << "[[event]]\nspec = \"sun:off@3\"\n[[event]]\nspec = \"node:table:remove@7\"\n";
    const std::vector<ResponseEvent> events = readTimeline(good.string());
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, EventKind::SunOff);
    EXPECT_EQ(events[1].frame, 7);
    const auto bad = dir / "bad.toml";
    std::ofstream(bad) << "[[event]]\nwhen = 3\n";
    try {
        readTimeline(bad.string());
        FAIL() << "a timeline event without spec must fail";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.toml"), std::string::npos) << e.what();
    }
    const auto wrong = dir / "wrong.toml";
    std::ofstream(wrong) << "[[event]]\nspec = \"sun:dim@1\"\n";
    EXPECT_THROW(readTimeline(wrong.string()), Error);
}
