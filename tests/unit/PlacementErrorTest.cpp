// The placement error estimate (renderer/probes/placement/PlacementError.h) that the lattice search
// ranks shifts by: zero where probes are exact, lower for a grid that resolves a shadow than
// for one that does not, the same on any thread count, and clear errors.
#include "probes/placement/PlacementError.h"
#include "ProbeTestScenes.h"
#include "core/Error.h"

#include <gtest/gtest.h>

using namespace pb::probes;
using namespace pb::test;

namespace {

// The scene's own sun and sky ("day").
Scenario lightOf(const pb::scene::Scene& s) {
    return resolveScenarios({}, {}, s).front();
}

ProbeVolume grid(glm::vec3 center, glm::vec3 half, glm::ivec3 counts) {
    ProbeVolume v;
    v.name = "grid";
    v.center = center;
    v.halfExtents = half;
    v.counts = counts;
    return v;
}

// The sunlit floor with a roof on legs over one corner: a shadow with sharp edges.
pb::scene::Scene shadedFloor() {
    pb::scene::Scene s = sunlitFloor();
    s.sun.toSun = glm::vec3(0.0f, 1.0f, 0.0f);
    const int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-3.0f, 1.0f, -3.0f}, {0.0f, 1.2f, 0.0f}, false, m));
    return s;
}

} // namespace

TEST(PlacementError, ExactWhereTheLightIsUniform) {
    // Every wall of the closed room emits and reflects alike: irradiance is pi Le (1 + rho)
    // after two bounces everywhere, which a lattice clear of the walls reproduces.
    pb::scene::Scene s = emissiveRoom(1.0f, 0.5f);
    const pb::raytrace::RayScene rs(s);
    PlacementErrorSettings es;
    es.points = 500;
    const PlacementErrorEstimate e(s, rs, lightOf(s), 0.01f, 0.25f, es);
    EXPECT_GT(e.pointCount(), 400u);
    // A lattice half a cell beyond the walls, as auto places it (the box reaches beyond the
    // walls: points outside a root volume are faded, ProbeSampler.h); the probes behind the
    // walls are left out by the bake. Two bounces, and one.
    const ProbeVolume v = grid({0, 0, 0}, glm::vec3(1.125f), {10, 10, 10});
    EXPECT_LT(e.relativeError({v}, false), 0.02);
    es.bounces = 1;
    const PlacementErrorEstimate one(s, rs, lightOf(s), 0.01f, 0.25f, es);
    EXPECT_LT(one.relativeError({v}, false), 0.02);
}

TEST(PlacementError, AGridThatResolvesTheShadowScoresLower) {
    pb::scene::Scene s = shadedFloor();
    const pb::raytrace::RayScene rs(s);
    PlacementErrorSettings es;
    es.points = 1000;
    const PlacementErrorEstimate e(s, rs, lightOf(s), 0.01f, 0.25f, es);
    // Over the same box around the whole scene (the slab's underside sees the sky too): probe
    // planes every 0.5 across and 0.25 up (mid-way between the roof's edges and faces),
    // against its 8 corners.
    const glm::vec3 c{0.0f, 0.5f, 0.0f}, h{3.25f, 1.125f, 3.25f};
    const double coarse = e.relativeError({grid(c, h, {2, 2, 2})}, false);
    const double fine = e.relativeError({grid(c, h, {14, 10, 14})}, false);
    EXPECT_LT(fine, 0.8 * coarse) << "fine " << fine << ", coarse " << coarse;
}

TEST(PlacementError, SameOnAnyThreadCountAndStableAcrossCalls) {
    pb::scene::Scene s = shadedFloor();
    const pb::raytrace::RayScene rs(s);
    const std::vector<ProbeVolume> v{grid({0, 0.5f, 0}, {3.25f, 1.125f, 3.25f}, {7, 5, 7})};
    PlacementErrorSettings es;
    es.points = 600;
    es.threads = 1;
    const PlacementErrorEstimate one(s, rs, lightOf(s), 0.01f, 0.25f, es);
    es.threads = 2;
    const PlacementErrorEstimate two(s, rs, lightOf(s), 0.01f, 0.25f, es);
    const double e1 = one.relativeError(v, false);
    EXPECT_EQ(e1, two.relativeError(v, false));
    EXPECT_EQ(e1, one.relativeError(v, false));
}

TEST(PlacementError, AVolumeThatMissesTheSceneScoresOne) {
    // No probe reaches a point: E = 0 where every truth is lit (above the 10% floor), so each
    // point's relative error is exactly 1.
    pb::scene::Scene s = sunlitFloor();
    const pb::raytrace::RayScene rs(s);
    PlacementErrorSettings es;
    es.points = 300;
    const PlacementErrorEstimate e(s, rs, lightOf(s), 0.01f, 0.5f, es);
    EXPECT_DOUBLE_EQ(e.relativeError({grid({100, 0, 0}, glm::vec3(1.0f), {2, 2, 2})}, false), 1.0);
}

TEST(PlacementError, NoSurfaceOrNoBounceIsAnError) {
    pb::scene::Scene empty = emptyScene();
    const pb::raytrace::RayScene nothing(empty);
    EXPECT_THROW(PlacementErrorEstimate(empty, nothing, lightOf(empty), 0.01f, 0.25f), pb::Error);
    pb::scene::Scene s = shadedFloor();
    const pb::raytrace::RayScene rs(s);
    PlacementErrorSettings es;
    es.bounces = 0;
    EXPECT_THROW(PlacementErrorEstimate(s, rs, lightOf(s), 0.01f, 0.25f, es), pb::Error);
}
