// The converged bake's pieces (issue 16): the emitter table samples triangles in proportion to
// their power; a probe under a small emissive panel, baked with emitter samples (MIS against
// its rays), matches the panel's irradiance integrated by quadrature, without bias, and far
// closer than its rays alone; a scene without emitters bakes bit for bit as without emitter
// samples; the noise target spends rounds where the noise is and lowers it, with the same
// bytes on any thread count; and two Cornell bakes that differ only in their seed agree to
// within 3% at surface points.
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"
#include "probes/bake/Baker.h"
#include "raytrace/EmitterTable.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RadiancePass.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "studies/common/SeedDifference.h"
#include "probes/placement/AutoPlacement.h"
#include "scene/BuiltinScenes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pb;
using namespace pb::probes;
using namespace pb::test;

namespace {

pb::raytrace::EmissiveTriangle tri(glm::vec3 a, glm::vec3 b, glm::vec3 c, float le, bool twoSided = false) {
    return {a, b, c, glm::normalize(glm::cross(b - a, c - a)), glm::vec3(le), twoSided, 0.0f, 0, 0};
}

// A 0.5 m square panel 1 m above the origin, emitting `le` downwards; black sky, sun off.
constexpr float kHalf = 0.25f, kHeight = 1.0f;
scene::Scene panelScene(float le) {
    scene::Scene s = emptyScene(glm::vec3(0.0f));
    const int m = addMaterial(s, glm::vec3(0.0f), glm::vec3(le));
    scene::Primitive p;
    p.material = m;
    addQuad(p, {-kHalf, kHeight, -kHalf}, {2 * kHalf, 0, 0}, {0, 0, 2 * kHalf}, {0, -1, 0});
    addInstance(s, p);
    return s;
}

// The panel's irradiance at the origin on a surface facing n, by a 200 x 200 midpoint rule:
// E(n) = L sum max(0, n.w) cos_l dA / d^2.
float panelIrradiance(float le, glm::vec3 n) {
    const int k = 200;
    const float da = (2 * kHalf / k) * (2 * kHalf / k);
    double e = 0.0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const glm::vec3 y(-kHalf + (i + 0.5f) * 2 * kHalf / k, kHeight,
                              -kHalf + (j + 0.5f) * 2 * kHalf / k);
            const float d2 = glm::dot(y, y);
            const glm::vec3 w = y / std::sqrt(d2);
            e += double(std::max(0.0f, glm::dot(n, w)) * w.y * da / d2);
        }
    return float(le * e);
}

// One probe at the origin, traced and convolved: its 6x6 interior texels (RGB).
std::vector<float> probeTexels(const pb::raytrace::RayScene& rs, const scene::Scene& s, int rays,
                               int emitterSamples, std::uint64_t stream) {
    RadianceSlab slab;
    slab.reset(1, rays);
    Scenario sc;
    sc.sun.enabled = false;
    sc.sky.radiance = glm::vec3(0.0f);
    const auto dirs = passDirections(rays, stream);
    RayCounters counters;
    slab.trace(0, rs, sc, s.lights, glm::mat3(1.0f), glm::vec3(0.0f), dirs, nullptr, counters,
               {emitterSamples, stream ^ 0x9e37ull}, 0);
    std::vector<float> out(kIrradianceInteriorTexels * 3);
    slab.convolve(0, ProbeConvolution(dirs), out.data());
    return out;
}

// One volume, the scene's own sun and sky, 64 rays, one round (no noise target).
BakeRequest oneVolumeBake(const scene::Scene& s, glm::vec3 center, glm::vec3 half,
                          glm::ivec3 counts) {
    BakeRequest req;
    req.volumes = {ProbeVolume{}};
    req.volumes[0].name = "v";
    req.volumes[0].center = center;
    req.volumes[0].halfExtents = half;
    req.volumes[0].counts = counts;
    req.scenarios = {Scenario{"day", s.sun, s.sky}};
    req.settings.raysPerProbe = 64;
    req.settings.noiseTarget = 0.0f;
    return req;
}

} // namespace

TEST(EmitterTable, PicksTrianglesInProportionToTheirPower) {
    // Powers 1 : 3 (twice the radiance) : 0 (left out) : 2 (double-sided, same area and radiance
    // as the first).
    std::vector<pb::raytrace::EmissiveTriangle> ts{tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f),
                                     tri({0, 0, 0}, {1, 0, 0}, {0, 1.5f, 0}, 2.0f),
                                     tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.0f),
                                     tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, true)};
    ts[1].geomID = 7;
    ts[1].primID = 3;
    const pb::raytrace::EmitterTable table(ts);
    ASSERT_EQ(table.size(), 3u);
    EXPECT_EQ(table.find(7, 3), 1);
    EXPECT_EQ(table.find(7, 2), -1);
    EXPECT_EQ(table.find(99, 0), -1);
    // The densities integrate to one over the emitters.
    double total = 0.0;
    for (int k = 0; k < 3; ++k)
        total += double(table.pdfArea(k)) * table.triangle(k).area;
    EXPECT_NEAR(total, 1.0, 1e-6);
    // Sampling frequencies follow the powers 1 : 3 : 2, and every point lies on its triangle.
    std::vector<int> hits(3, 0);
    std::uint64_t state = 42;
    const int n = 60000;
    for (int i = 0; i < n; ++i) {
        const pb::raytrace::EmitterSample s =
            table.sample(uniformFloat(state), uniformFloat(state), uniformFloat(state));
        ASSERT_GE(s.triangle, 0);
        ++hits[size_t(s.triangle)];
        const pb::raytrace::EmissiveTriangle& t = table.triangle(s.triangle);
        EXPECT_NEAR(glm::dot(s.point - t.a, t.normal), 0.0f, 1e-5f);
        EXPECT_GE(s.point.x, -1e-6f);
        EXPECT_GE(s.point.y, -1e-6f);
    }
    EXPECT_NEAR(hits[0] / double(n), 1.0 / 6.0, 0.01);
    EXPECT_NEAR(hits[1] / double(n), 3.0 / 6.0, 0.01);
    EXPECT_NEAR(hits[2] / double(n), 2.0 / 6.0, 0.01);
    EXPECT_TRUE(pb::raytrace::EmitterTable().empty());
}

TEST(EmitterSampling, AProbeUnderAPanelMatchesTheQuadratureWithoutBias) {
    const float le = 10.0f;
    const scene::Scene s = panelScene(le);
    const pb::raytrace::RayScene rs(s);
    ASSERT_EQ(rs.emitters().size(), 2u);
    const float top = panelIrradiance(le, {0, 1, 0});
    ASSERT_GT(top, 1.0f);
    // Per texel facing the panel: the error of one probe, and the mean of 24 independent ones.
    double errNee = 0.0, errRays = 0.0;
    std::vector<double> meanNee(kIrradianceInteriorTexels, 0.0);
    const int trials = 24;
    int counted = 0;
    for (int trial = 0; trial < trials; ++trial) {
        const std::uint64_t stream = 1000 + std::uint64_t(trial);
        const std::vector<float> nee = probeTexels(rs, s, 256, 512, stream);
        const std::vector<float> rays = probeTexels(rs, s, 256, 0, stream);
        for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
            const glm::vec3 n = octTexelDirection(t % kIrradianceInterior, t / kIrradianceInterior,
                                                  kIrradianceInterior);
            const float ref = panelIrradiance(le, n);
            if (ref < 0.2f * top) continue;
            errNee += std::fabs(nee[3 * size_t(t)] - ref) / ref;
            errRays += std::fabs(rays[3 * size_t(t)] - ref) / ref;
            meanNee[size_t(t)] += nee[3 * size_t(t)] / trials;
            if (trial == 0) ++counted;
        }
    }
    ASSERT_GT(counted, 0);
    errNee /= counted * trials;
    errRays /= counted * trials;
    EXPECT_LT(errNee, 0.03) << "one probe with emitter samples is within a few percent";
    EXPECT_LT(errNee * 4, errRays) << "and far closer than its rays alone (" << errRays << ")";
    for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
        const glm::vec3 n = octTexelDirection(t % kIrradianceInterior, t / kIrradianceInterior,
                                              kIrradianceInterior);
        const float ref = panelIrradiance(le, n);
        if (ref >= 0.2f * top) {
            EXPECT_NEAR(meanNee[size_t(t)], ref, 0.01 * ref) << "texel " << t;
        }
    }
}

TEST(EmitterSampling, WithoutEmittersTheSamplesChangeNothing) {
    const scene::Scene s = sunlitFloor();
    const pb::raytrace::RayScene rs(s);
    ASSERT_TRUE(rs.emitters().empty());
    BakeRequest req = oneVolumeBake(s, {0, 1, 0}, {2, 1, 2}, {4, 3, 4});
    req.settings.emitterSamples = 0;
    const ProbeSet a = bakeProbes(s, req);
    req.settings.emitterSamples = 512;
    const ProbeSet b = bakeProbes(s, req);
    EXPECT_EQ(a.irradiance[0][0].texels, b.irradiance[0][0].texels);
}

TEST(NoiseTarget, MoreRoundsWhereTheNoiseIsTheSameBytesOnAnyThreadCount) {
    const scene::Scene s = scene::makeCornellScene();
    BakeRequest req = oneVolumeBake(s, {0, 1, 0}, glm::vec3(0.95f), {5, 5, 5});
    BakeStats one, converged, single;
    bakeProbes(s, req, &one);
    EXPECT_EQ(one.extraRoundRays, 0u);
    EXPECT_EQ(one.noisyProbePasses, 0u);
    EXPECT_GT(one.noiseMean, 0.0);
    req.settings.noiseTarget = 0.03f;
    req.threads = 2;
    const ProbeSet a = bakeProbes(s, req, &converged);
    EXPECT_GT(converged.noisyProbePasses, 0u);
    EXPECT_GT(converged.extraRoundRays, 0u);
    EXPECT_LT(converged.noiseMean, 0.5 * one.noiseMean) << one.noiseMean;
    EXPECT_EQ(converged.tracedProbePasses, one.tracedProbePasses);
    req.threads = 1;
    const ProbeSet b = bakeProbes(s, req, &single);
    EXPECT_EQ(a.irradiance[0][0].texels, b.irradiance[0][0].texels);
    req.settings.noiseTarget = 1.5f;
    EXPECT_THROW(bakeProbes(s, req), Error);
    req.settings.noiseTarget = -0.1f;
    EXPECT_THROW(bakeProbes(s, req), Error);
}

// Issue 16's "done when": two default Cornell bakes with different seeds agree to <= 3% mean
// relative difference at surface points (the default placement, stored sparse; without the
// lattice search, which places but does not bake the result).
TEST(NoiseTarget, TwoCornellBakesWithDifferentSeedsAgreeWithinThreePercent) {
    const scene::Scene s = scene::makeCornellScene();
    AutoPlacementRequest place;
    place.sparse = true;
    place.latticeSearch = false;
    BakeRequest req;
    req.volumes = placeAutoVolumes(s, place).volumes;
    req.scenarios = {Scenario{"day", s.sun, s.sky}};
    req.sparse = true;
    const ProbeSet a = bakeProbes(s, req);
    req.settings.seed = 2;
    const ProbeSet b = bakeProbes(s, req);
    const studies::SeedDifference d = studies::seedDifference(s, a, b, 1000);
    EXPECT_GT(d.points, 500u);
    EXPECT_LT(d.mean, 0.03) << "median " << d.median << ", p90 " << d.p90;
}
