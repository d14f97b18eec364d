// Direct light at bake hits (renderer/probes/bake/DirectLight.h) against the analytic formulas,
// and the work-sharing loop the bake runs on.
#include "ProbeTestScenes.h"
#include "probes/bake/DirectLight.h"
#include "core/ParallelFor.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <thread>

using namespace pb::probes;
using pb::parallelFor;
using namespace pb::test;

namespace {

Scenario noSun() {
    Scenario s;
    s.name = "test";
    s.sun.enabled = false;
    return s;
}

pb::scene::Light pointLight(glm::vec3 pos, float candela) {
    pb::scene::Light l;
    l.type = pb::scene::LightType::Point;
    l.position = pos;
    l.intensity = candela;
    l.color = glm::vec3(1.0f);
    return l;
}

} // namespace

TEST(BakeDirectLight, SunIsIntensityTimesCosineAndShadowed) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.0f));
    int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-0.5f, 2, -0.5f}, {0.5f, 2.2f, 0.5f}, false, m)); // a roof
    pb::raytrace::RayScene rs(s);
    Scenario sc = noSun();
    sc.sun.enabled = true;
    sc.sun.intensity = 3.0f;
    sc.sun.color = glm::vec3(1.0f);
    sc.sun.toSun = glm::normalize(glm::vec3(1, 1, 0));
    std::uint64_t shadow = 0;
    glm::vec3 e = directIrradiance(rs, sc, {}, {5, 0, 0}, {0, 1, 0}, shadow);
    EXPECT_NEAR(e.x, 3.0f * std::sqrt(0.5f), 1e-5f);
    EXPECT_EQ(shadow, 1u);
    sc.sun.toSun = glm::vec3(0, 1, 0);
    EXPECT_EQ(directIrradiance(rs, sc, {}, {0, 0, 0}, {0, 1, 0}, shadow), glm::vec3(0.0f));
    EXPECT_EQ(directIrradiance(rs, sc, {}, {5, 0, 0}, {0, -1, 0}, shadow), glm::vec3(0.0f));
}

TEST(BakeDirectLight, PointLightFollowsInverseSquareAndRange) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.0f));
    pb::raytrace::RayScene rs(s);
    std::uint64_t shadow = 0;
    std::vector<pb::scene::Light> lights{pointLight({0, 2, 0}, 8.0f)};
    EXPECT_NEAR(directIrradiance(rs, noSun(), lights, {0, 0, 0}, {0, 1, 0}, shadow).x, 2.0f, 1e-5f);
    // 45 degrees off: cos / d^2 = 0.7071 / 8.
    EXPECT_NEAR(directIrradiance(rs, noSun(), lights, {2, 0, 0}, {0, 1, 0}, shadow).x,
                8.0f * std::sqrt(0.5f) / 8.0f, 1e-5f);
    lights[0].range = 4.0f; // glTF window: (1 - (d/r)^4)^2 at d = 2 -> (15/16)^2
    EXPECT_NEAR(directIrradiance(rs, noSun(), lights, {0, 0, 0}, {0, 1, 0}, shadow).x,
                2.0f * (15.0f / 16.0f) * (15.0f / 16.0f), 1e-5f);
    lights[0].range = 1.0f;
    EXPECT_EQ(directIrradiance(rs, noSun(), lights, {0, 0, 0}, {0, 1, 0}, shadow).x, 0.0f);
}

TEST(BakeDirectLight, SpotConeAndShadowRays) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.0f));
    int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({2.9f, 0.5f, -0.5f}, {3.1f, 1.5f, 0.5f}, false, m)); // occluder
    pb::raytrace::RayScene rs(s);
    pb::scene::Light spot = pointLight({0, 4, 0}, 16.0f);
    spot.type = pb::scene::LightType::Spot;
    spot.direction = {0, -1, 0};
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.4f;
    std::uint64_t shadow = 0;
    EXPECT_NEAR(directIrradiance(rs, noSun(), {spot}, {0, 0, 0}, {0, 1, 0}, shadow).x, 1.0f, 1e-5f);
    EXPECT_EQ(directIrradiance(rs, noSun(), {spot}, {4, 0, 0}, {0, 1, 0}, shadow).x,
              0.0f); // outside
    // A point light whose path to the receiver crosses the occluder.
    std::vector<pb::scene::Light> side{pointLight({6, 1, 0}, 9.0f)};
    std::uint64_t before = shadow;
    EXPECT_EQ(directIrradiance(rs, noSun(), side, {0, 1, 0}, {1, 0, 0}, shadow).x, 0.0f);
    EXPECT_EQ(shadow, before + 1);
    EXPECT_NEAR(directIrradiance(rs, noSun(), side, {0, 1, 3}, {0, 0, -1}, shadow).x,
                9.0f / 45.0f * (3.0f / std::sqrt(45.0f)), 1e-5f);
}

TEST(BakeParallelFor, RunsEveryItemOnceAndRethrows) {
    for (int threads : {1, 2, 5}) {
        std::vector<std::atomic<int>> hits(1000);
        parallelFor(hits.size(), threads, [&](std::size_t i, int t) {
            EXPECT_LT(t, threads);
            ++hits[i];
        });
        for (auto& h : hits)
            EXPECT_EQ(h.load(), 1);
    }
    std::size_t lastTick = 0;
    parallelFor(
        64, 2, [](std::size_t, int) {}, [&](std::size_t done) { lastTick = done; });
    EXPECT_EQ(lastTick, 64u);
    EXPECT_THROW(parallelFor(100, 2,
                             [](std::size_t i, int) {
                                 if (i == 37) throw std::runtime_error("boom");
                             }),
                 std::runtime_error);
    parallelFor(0, 2, [](std::size_t, int) { FAIL(); });
}

TEST(BakeParallelFor, ZeroThreadsMeansEveryCore) {
    // `threads` 0 is "all cores" wherever the project takes a thread count; seven callers
    // passed 0 and ran on one thread (the truth's path tracer among them). Two items, each
    // waiting until a second thread has entered: on one thread the first waits out its
    // 10 s and the run fails. (A one-core machine has nothing to show.)
    const int cores = pb::resolveThreadCount(0);
    if (cores < 2) GTEST_SKIP() << "one hardware thread";
    std::atomic<int> entered{0}, maxThread{0};
    parallelFor(2, 0, [&](std::size_t, int t) {
        ++entered;
        int m = maxThread.load();
        while (t > m && !maxThread.compare_exchange_weak(m, t)) {
        }
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (entered.load() < 2 && std::chrono::steady_clock::now() < until)
            std::this_thread::yield();
    });
    EXPECT_EQ(entered.load(), 2);
    EXPECT_EQ(maxThread.load(), 1) << "0 threads ran the two items on one thread";
    // Never more threads than items, whatever `threads` asks.
    parallelFor(1, 0, [&](std::size_t, int t) { EXPECT_EQ(t, 0); });
}

TEST(BakeParallelFor, TheCallingThreadIsWorkerZeroAndTicks) {
    // Progress callbacks (a terminal bar) run on the caller's thread, never on a helper.
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<int> zeroElsewhere{0}, ticksElsewhere{0};
    std::vector<std::size_t> ticks;
    parallelFor(
        2000, 2,
        [&](std::size_t, int t) {
            if (t == 0 && std::this_thread::get_id() != caller) ++zeroElsewhere;
            std::this_thread::sleep_for(std::chrono::microseconds(150)); // ~150 ms in all
        },
        [&](std::size_t done) {
            if (std::this_thread::get_id() != caller) ++ticksElsewhere;
            ticks.push_back(done);
        });
    EXPECT_EQ(zeroElsewhere.load(), 0);
    EXPECT_EQ(ticksElsewhere.load(), 0);
    ASSERT_FALSE(ticks.empty());
    EXPECT_EQ(ticks.back(), 2000u);
    for (std::size_t i = 1; i < ticks.size(); ++i)
        EXPECT_LE(ticks[i - 1], ticks[i]); // progress never goes back
}
