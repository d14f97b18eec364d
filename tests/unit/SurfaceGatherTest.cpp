// The direct gather at surface points (renderer/probes/bake/SurfaceGather.h), bench_placement's
// ground truth, against closed forms: a uniform sky, an emissive room with and without the
// probes of an earlier bounce, and a sunlit floor seen from above (a rectangle's view factor).
#include "probes/bake/SurfaceGather.h"
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "probes/bake/Baker.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb::probes;
using namespace pb::test;

namespace {

// The scene's own sun and sky ("day").
Scenario scenarioOf(const pb::scene::Scene& s) {
    return resolveScenarios({}, {}, s).front();
}

// View factor from a point to a parallel rectangle [0,a]x[0,b] whose corner lies straight
// below it at distance h (the standard corner formula).
double cornerViewFactor(double a, double b, double h) {
    const double A = a / h, B = b / h;
    const double sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * M_PI);
}

} // namespace

TEST(SurfaceGather, CosineSpiralIsUnitAndCosineDistributed) {
    const std::vector<glm::vec3> d = cosineHemisphereSpiral(4096);
    ASSERT_EQ(d.size(), 4096u);
    double meanCos = 0.0;
    for (const glm::vec3& v : d) {
        EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
        EXPECT_GT(v.z, 0.0f);
        meanCos += v.z;
    }
    // E[cos] under a cosine density is 2/3 (uniform over the hemisphere would give 1/2).
    EXPECT_NEAR(meanCos / double(d.size()), 2.0 / 3.0, 1e-3);
}

TEST(SurfaceGather, OpenSkyGivesPiTimesSky) {
    pb::scene::Scene s = sunlitFloor(); // the sun lights the floor, not the point's hemisphere
    pb::raytrace::RayScene rs(s);
    std::vector<GatherPoint> pts{{{0, 0, 0}, {0, 1, 0}}, {{1.5f, 0, -2}, {0, 1, 0}}};
    GatherSettings g;
    g.rays = 256;
    std::vector<glm::vec3> e = gatherIrradiance(rs, scenarioOf(s), s.lights, pts, nullptr, g);
    ASSERT_EQ(e.size(), 2u);
    for (const glm::vec3& v : e)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(v[c], float(M_PI) * s.sky.radiance[c], 1e-4f * float(M_PI));
}

TEST(SurfaceGather, EmissiveRoomWithAndWithoutEarlierBounces) {
    const float le = 1.0f, rho = 0.5f;
    pb::scene::Scene s = emissiveRoom(le, rho);
    pb::raytrace::RayScene rs(s);
    std::vector<GatherPoint> pts{{{0, -1, 0}, {0, 1, 0}}, {{1, 0.3f, 0.2f}, {-1, 0, 0}}};
    GatherSettings g;
    g.rays = 128;
    // One bounce: every hit shows its emission.
    for (const glm::vec3& v : gatherIrradiance(rs, scenarioOf(s), s.lights, pts, nullptr, g))
        EXPECT_NEAR(v.g, float(M_PI) * le, 1e-3f);
    // With one-bounce probes (E = pi Le everywhere) at the hits: Le (1 + rho) arrives.
    BakeRequest r;
    ProbeVolume v;
    v.name = "room";
    v.halfExtents = glm::vec3(0.7f);
    v.counts = glm::ivec3(3);
    r.volumes = {v};
    r.scenarios = resolveScenarios({}, {}, s);
    r.settings.raysPerProbe = 128;
    r.settings.bounces = 1;
    ProbeSet set = bakeProbes(s, r);
    ProbeSampler probes(set, 0);
    for (const glm::vec3& e : gatherIrradiance(rs, scenarioOf(s), s.lights, pts, &probes, g))
        EXPECT_NEAR(e.g, float(M_PI) * le * (1.0f + rho), 0.01f * float(M_PI));
}

TEST(SurfaceGather, SunlitFloorSeenFromAboveMatchesItsViewFactor) {
    pb::scene::Scene s = sunlitFloor(); // a 6 x 6 slab, top at y = 0, albedo 0.6
    pb::raytrace::RayScene rs(s);
    const float h = 0.5f;
    std::vector<GatherPoint> pts{{{0, h, 0}, {0, -1, 0}}};
    GatherSettings g;
    g.rays = 4096;
    const glm::vec3 e = gatherIrradiance(rs, scenarioOf(s), s.lights, pts, nullptr, g)[0];
    // The slab top is sunlit everywhere (nothing stands on it): radiance 0.6/pi * E_sun.
    const double f = 4.0 * cornerViewFactor(3.0, 3.0, h);
    for (int c = 0; c < 3; ++c) {
        const double sun = double(s.sun.color[c] * s.sun.intensity) * double(s.sun.toSun.y);
        const double expected = 0.6 * sun * f + M_PI * double(s.sky.radiance[c]) * (1.0 - f);
        EXPECT_NEAR(double(e[c]), expected, 0.01 * expected) << "channel " << c;
    }
}

TEST(SurfaceGather, SameResultOnAnyThreadCount) {
    pb::scene::Scene s = sunlitFloor();
    pb::raytrace::RayScene rs(s);
    std::vector<GatherPoint> pts;
    for (int i = 0; i < 300; ++i) // more than one batch at 4096 rays
        pts.push_back(
            {{-2.9f + 0.019f * float(i), 0.3f, 0.1f}, glm::normalize(glm::vec3(0.2f, -1, 0))});
    GatherSettings g;
    g.rays = 1024;
    g.threads = 1;
    std::vector<glm::vec3> one = gatherIrradiance(rs, scenarioOf(s), s.lights, pts, nullptr, g);
    g.threads = 3;
    std::vector<glm::vec3> three = gatherIrradiance(rs, scenarioOf(s), s.lights, pts, nullptr, g);
    EXPECT_EQ(one, three);
}

TEST(SurfaceGather, ZeroRaysIsAnError) {
    pb::scene::Scene s = sunlitFloor();
    pb::raytrace::RayScene rs(s);
    GatherSettings g;
    g.rays = 0;
    EXPECT_THROW(
        gatherIrradiance(rs, scenarioOf(s), s.lights, {{{0, 1, 0}, {0, 1, 0}}}, nullptr, g),
        pb::Error);
}

// The sphere gather (mid-air truth, issue 18): in the emissive room every direction sees Le,
// so every normal gets pi Le; above the sunlit floor, the downward normal sees the floor as
// the hemisphere gather does, the upward one the sky, from the same rays.
TEST(SurfaceGather, SphereGatherMatchesTheHemisphereGatherPerNormal) {
    const float le = 1.0f;
    pb::scene::Scene room = emissiveRoom(le, 0.5f);
    pb::raytrace::RayScene roomRays(room);
    GatherSettings g;
    g.rays = 1024;
    const std::vector<glm::vec3> axes = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                         {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<glm::vec3> e = gatherIrradianceSphere(
        roomRays, scenarioOf(room), room.lights, {{0.1f, 0.2f, -0.3f}}, axes, nullptr, g);
    ASSERT_EQ(e.size(), axes.size());
    for (const glm::vec3& v : e)
        EXPECT_NEAR(v.g, float(M_PI) * le, 1e-3f);

    pb::scene::Scene s = sunlitFloor();
    pb::raytrace::RayScene rs(s);
    g.rays = 4096;
    const glm::vec3 p(0.0f, 0.5f, 0.0f);
    const std::vector<glm::vec3> sphere = gatherIrradianceSphere(
        rs, scenarioOf(s), s.lights, {p}, {{0, -1, 0}, {0, 1, 0}}, nullptr, g);
    const glm::vec3 down = gatherIrradiance(rs, scenarioOf(s), s.lights, {{p, {0, -1, 0}}},
                                            nullptr, g)[0];
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sphere[0][c], down[c], 0.02f * down[c]) << "channel " << c;
        EXPECT_NEAR(sphere[1][c], float(M_PI) * s.sky.radiance[c], 1e-3f) << "channel " << c;
    }
}
