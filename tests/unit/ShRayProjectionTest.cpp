// The bake's SH probes are the Monte Carlo projection of the radiance pass's own samples
// (issue 19: 4 pi / N sum L(w) Y(w) over the rays, plus the emitter and lit-surface samples'
// shares), not a re-projection of the filtered irradiance map. Checked against a closed form:
// under a uniform sky over an infinite black floor the radiance is 1 above the horizon and 0
// below, whose SH are c00 = 2 pi Y00 = sqrt(pi), c(1,y) = pi sqrt(3 / 4pi) and every other
// coefficient 0. The map's projection (what the bake did before) is measured beside it.
#include "unit/ProbeTestScenes.h"

#include "probes/ShIrradiance.h"
#include "probes/bake/Baker.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

constexpr float kPi = 3.14159265f;

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
    c[0] = glm::vec3(std::sqrt(kPi));
    c[1] = glm::vec3(kPi * std::sqrt(3.0f / (4.0f * kPi)));
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
