// The bake's SH probes are the Monte Carlo projection of the radiance pass's own samples
// (issue 19: 4 pi / N sum L(w) Y(w) over the rays, plus the emitter and lit-surface samples'
// shares), not a re-projection of the filtered irradiance map. Checked against a closed form:
// under a uniform sky over an infinite black floor the radiance is 1 above the horizon and 0
// below, whose SH are c00 = 2 pi Y00 = sqrt(pi), c(1,y) = pi sqrt(3 / 4pi) and every other
// coefficient 0. The map's projection (what the bake did before) is measured beside it.
#include "unit/ProbeTestScenes.h"

#include "probes/sh/ShIrradiance.h"
#include "probes/bake/Baker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

constexpr float kShRayProjectionPi = 3.14159265f;

pb::scene::Scene skyOverBlackFloor() {
    pb::scene::Scene s = pb::test::emptyScene(glm::vec3(1.0f));
    pb::scene::Primitive floor;
    floor.material = pb::test::addMaterial(s, glm::vec3(0.0f));
    pb::test::addQuad(floor, {-5000, 0, -5000}, {10000, 0, 0}, {0, 0, 10000}, {0, 1, 0});
    pb::test::addInstance(s, std::move(floor));
    return s;
}

ShCoefficients exactHalfSky() {
    ShCoefficients c{};
    c[0] = glm::vec3(std::sqrt(kShRayProjectionPi));
    c[1] = glm::vec3(kShRayProjectionPi * std::sqrt(3.0f / (4.0f * kShRayProjectionPi)));
    return c;
}

// Sum over the 9 coefficients of |c - exact| (green), over exact c00.
double relativeError(const glm::vec3* c) {
    const ShCoefficients e = exactHalfSky();
    double sum = 0;
    for (int k = 0; k < kShL2Coefficients; ++k)
        sum += std::abs(double(c[k].y) - double(e[size_t(k)].y));
    return sum / double(e[0].y);
}

} // namespace

TEST(ShRayProjection, BakedShIsTheRaySamplesProjectionOfAHalfSky) {
    const pb::scene::Scene s = skyOverBlackFloor();
    BakeRequest r;
    ProbeVolume v;
    v.name = "v";
    v.center = {0, 1.5f, 0};
    v.halfExtents = {1, 0.5f, 1};
    v.counts = {2, 2, 2};
    r.volumes = {v};
    r.scenarios = resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 256;
    r.settings.bounces = 1;
    const ProbeSet set = bakeProbes(s, r);
    ASSERT_TRUE(set.hasSh());
    const std::vector<glm::vec3> map =
        projectIrradianceTexture(set.volumes[0], set.states[0], set.irradiance[0][0]);
    double rays = 0, maps = 0;
    for (int p = 0; p < v.probeCount(); ++p) {
        ASSERT_TRUE(set.states[0][size_t(p)].valid) << p;
        rays += relativeError(&set.sh[0][0][size_t(p) * 9]) / v.probeCount();
        maps += relativeError(&map[size_t(p) * 9]) / v.probeCount();
    }
    std::printf("[ sh projection ] half sky, 256 rays: sum |c - exact| / c00, rays %.4f, map "
                "%.4f\n",
                rays, maps);
    // One ray of 256 is 0.8% of c00 per coefficient: about a ray per coefficient at most.
    EXPECT_LT(rays, 0.1);
    EXPECT_LT(rays, maps) << "the map projection was closer: the rays are not what is stored";
}

// A nested child's outer ring is blended towards the parent on the map after the rays
// (NestingBlend.h), so those probes - and only those - store the map's projection of their
// final tile; every other probe stores its rays' projection.
TEST(ShRayProjection, BlendedRingProbesTakeTheMapProjection) {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    BakeRequest r;
    ProbeVolume root, child;
    root.name = "root";
    root.center = {0, 1, 0};
    root.halfExtents = {2, 0.9f, 2};
    root.counts = {4, 2, 4};
    child.name = "child";
    child.parent = "root";
    child.center = {0, 1, 0};
    child.halfExtents = {1, 0.6f, 1};
    child.counts = {4, 3, 4};
    r.volumes = {root, child};
    r.scenarios = resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 64;
    const ProbeSet set = bakeProbes(s, r);
    const ProbeVolume& v = set.volumes[1];
    int ring = 0, inner = 0;
    for (int p = 0; p < v.probeCount(); ++p) {
        const glm::ivec3 c = v.probeCoords(p);
        const ProbeState& st = set.states[1][size_t(p)];
        if (!st.valid) continue;
        // The stored map is quantised to RGBA16F after the SH were taken: a match is within
        // half-float rounding (2^-11 relative per texel, and the SH's own), well below 2e-3;
        // 64 rays and the map's filtering differ by more than twice that.
        const ShCoefficients map = projectIrradianceTile(c, set.irradiance[0][1]);
        double diff = 0;
        for (int k = 0; k < kShL2Coefficients; ++k)
            diff = std::max(diff, double(glm::length(set.sh[0][1][size_t(p) * 9 + size_t(k)] -
                                                     map[size_t(k)])));
        diff /= std::max(double(glm::length(map[0])), 1e-6);
        const bool blended = c.x == 0 || c.x == 3 || c.y == 0 || c.y == 2 || c.z == 0 || c.z == 3;
        if (blended && st.offset == glm::vec3(0.0f)) {
            ++ring;
            EXPECT_LT(diff, 2e-3) << "ring probe " << p;
        } else if (!blended) {
            ++inner;
            EXPECT_GT(diff, 4e-3) << "inner probe " << p << " stores the map's projection";
        }
    }
    EXPECT_GT(ring, 10);
    EXPECT_GT(inner, 1);
}
