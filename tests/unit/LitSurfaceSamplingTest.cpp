// Lit-surface samples (issue 16, the converged bake): the alias table picks in proportion to
// its weights; the lit-surface table covers exactly the surfaces the sun reaches, its sampling
// density is the one a ray hit looks up (what MIS needs), and it integrates to the lit area;
// a probe above a small sunlit square, baked with lit-surface samples against its rays,
// matches the square's reflected light integrated by quadrature, without bias, and far closer
// than its rays alone; a scene without sun or punctual lights has nothing to sample and bakes
// the same bytes as without samples; any thread count bakes the same bytes.
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "probes/bake/Baker.h"
#include "probes/ProbeLayout.h"
#include "raytrace/AliasTable.h"
#include "probes/bake/LitSurfaces.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RadiancePass.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "probes/Octahedral.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace pb;
using namespace pb::probes;
using namespace pb::test;

namespace {

constexpr float kLitSurfaceSamplingHalf = 0.25f, kBelow = 1.0f, kAlbedo = 0.8f;

Scenario sunFromAbove(float intensity) {
    Scenario sc;
    sc.sun.enabled = true;
    sc.sun.toSun = glm::vec3(0, 1, 0);
    sc.sun.color = glm::vec3(1.0f);
    sc.sun.intensity = intensity;
    sc.sky.radiance = glm::vec3(0.0f);
    return sc;
}

// A 0.5 m grey square 1 m below the origin, facing up; black sky. With `blocker`, an opaque
// black card 0.5 m above the square's x > 0 half shades that half from a sun overhead.
scene::Scene squareScene(bool blocker) {
    scene::Scene s = emptyScene(glm::vec3(0.0f));
    const int grey = addMaterial(s, glm::vec3(kAlbedo));
    scene::Primitive p;
    p.material = grey;
    addQuad(p, {-kLitSurfaceSamplingHalf, -kBelow, -kLitSurfaceSamplingHalf},
            {2 * kLitSurfaceSamplingHalf, 0, 0}, {0, 0, 2 * kLitSurfaceSamplingHalf}, {0, 1, 0});
    addInstance(s, p);
    if (blocker) {
        const int black = addMaterial(s, glm::vec3(0.0f));
        scene::Primitive card;
        card.material = black;
        addQuad(card, {0, -0.5f, -kLitSurfaceSamplingHalf}, {kLitSurfaceSamplingHalf, 0, 0},
                {0, 0, 2 * kLitSurfaceSamplingHalf}, {0, 1, 0});
        addInstance(s, card);
    }
    return s;
}

// The square's reflected light at the origin on a surface facing n, by a 200 x 200 midpoint
// rule: uniform radiance L = albedo / pi * E_sun, E(n) = L sum max(0, n.w) cos_l dA / d^2.
float squareIrradiance(float sun, glm::vec3 n) {
    const int k = 200;
    const float le = kAlbedo / float(M_PI) * sun,
                da = (2 * kLitSurfaceSamplingHalf / k) * (2 * kLitSurfaceSamplingHalf / k);
    double e = 0.0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const glm::vec3 y(
                -kLitSurfaceSamplingHalf + (i + 0.5f) * 2 * kLitSurfaceSamplingHalf / k, -kBelow,
                -kLitSurfaceSamplingHalf + (j + 0.5f) * 2 * kLitSurfaceSamplingHalf / k);
            const float d2 = glm::dot(y, y);
            const glm::vec3 w = y / std::sqrt(d2);
            e += double(std::max(0.0f, glm::dot(n, w)) * -w.y * da / d2);
        }
    return float(le * e);
}

// One probe at the origin, one round, convolved: its 6x6 interior texels (RGB).
std::vector<float> litSurfaceSamplingProbeTexels(const pb::raytrace::RayScene& rs, const scene::Scene& s,
                                                 const Scenario& sc, const LitSurfaces& lit,
                                                 int rays, int litSamples, std::uint64_t stream) {
    RadianceSlab slab;
    slab.reset(1, rays);
    const auto dirs = passDirections(rays, stream);
    RayCounters counters;
    slab.trace(0, rs, sc, s.lights, glm::mat3(1.0f), glm::vec3(0.0f), dirs, nullptr, counters,
               {0, stream ^ 0x9e37ull, litSamples, &lit}, 0);
    std::vector<float> out(kIrradianceInteriorTexels * 3);
    slab.convolve(0, ProbeConvolution(dirs), out.data());
    return out;
}

// Mean relative error of the texels facing down (where the square is) against quadrature
// (`texels`: a texture's or a plain float vector).
template <class Floats> double meanRelativeError(const Floats& texels, float sun) {
    double sum = 0.0;
    int n = 0;
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i) {
            const glm::vec3 dir = octTexelDirection(i, j, kIrradianceInterior);
            const float truth = squareIrradiance(sun, dir);
            if (truth < 1e-3f * squareIrradiance(sun, {0, -1, 0})) continue;
            sum += std::fabs(texels[size_t(j * kIrradianceInterior + i) * 3] - truth) / truth;
            ++n;
        }
    return n ? sum / n : 1e9;
}

} // namespace

TEST(AliasTable, PicksIndicesInProportionToTheirWeights) {
    const pb::raytrace::AliasTable t({1.0, 0.0, 3.0, 2.0});
    ASSERT_FALSE(t.empty());
    EXPECT_DOUBLE_EQ(t.probability(0), 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(t.probability(1), 0.0);
    EXPECT_DOUBLE_EQ(t.probability(2), 0.5);
    const int n = 60000;
    std::vector<int> count(4, 0);
    for (int k = 0; k < n; ++k)
        ++count[t.pick((float(k) + 0.5f) / float(n))];
    EXPECT_EQ(count[1], 0);
    EXPECT_NEAR(count[0] / double(n), 1.0 / 6.0, 1e-3);
    EXPECT_NEAR(count[2] / double(n), 0.5, 1e-3);
    EXPECT_NEAR(count[3] / double(n), 1.0 / 3.0, 1e-3);
    // Nothing to pick from: no weights, all zero, or a negative or non-finite one.
    EXPECT_TRUE(pb::raytrace::AliasTable(std::vector<double>{}).empty());
    EXPECT_TRUE(pb::raytrace::AliasTable({0.0, 0.0}).empty());
    EXPECT_TRUE(pb::raytrace::AliasTable({1.0, -1.0}).empty());
    EXPECT_TRUE(pb::raytrace::AliasTable({1.0, std::nan("")}).empty());
}

TEST(LitSurfaces, SamplesOnlyTheSunlitPartWithTheDensityARayHitLooksUp) {
    const scene::Scene s = squareScene(true);
    const pb::raytrace::RayScene rs(s);
    std::uint64_t shadow = 0;
    const LitSurfaces lit(rs, sunFromAbove(1.0f), s.lights, 2, shadow);
    ASSERT_FALSE(lit.empty());
    EXPECT_GT(shadow, 0u);
    std::uint64_t state = 7;
    const int n = 20000;
    double inverseDensity = 0.0;
    for (int k = 0; k < n; ++k) {
        const float u0 = uniformFloat(state), u1 = uniformFloat(state), u2 = uniformFloat(state);
        const LitPatchSample p = lit.sample(u0, u1, u2);
        ASSERT_GE(p.entry, 0);
        // On the grey square's sunlit half, never on the card (black) or in its shadow (the
        // patches are at most 1/64 of the scene across, so only the shadow's edge can differ).
        EXPECT_NEAR(p.point.y, -kBelow, 1e-5f);
        EXPECT_LT(p.point.x, 0.02f);
        EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
        EXPECT_NEAR(p.albedoOverPi.r, kAlbedo / float(M_PI), 1e-6f);
        // What MIS needs: the density a ray hitting this point looks up is the sampled one.
        const LitPatchSide side = lit.side(std::size_t(p.entry));
        EXPECT_FLOAT_EQ(lit.pdfArea(side.geomID, side.primID, side.back, p.point), p.pdfArea);
        inverseDensity += 1.0 / double(p.pdfArea) / n;
    }
    // E[1 / pdf] is the area sampled: the sunlit half of the square.
    EXPECT_NEAR(inverseDensity, 2 * kLitSurfaceSamplingHalf * kLitSurfaceSamplingHalf,
                0.05 * 2 * kLitSurfaceSamplingHalf * kLitSurfaceSamplingHalf);
    // The shadowed half and the square's underside are not sampled: a ray that hits them
    // keeps its full weight.
    const pb::raytrace::RayHit shaded = rs.intersect({0.1f, 0.0f, 0.0f}, {0, -1, 0});
    ASSERT_TRUE(shaded.hit());
    EXPECT_EQ(lit.pdfArea(shaded.geomID, shaded.primID, false, {0.1f, -0.5f, 0.0f}), 0.0f);
    const pb::raytrace::RayHit square = rs.intersect({-0.1f, -2.0f, 0.0f}, {0, 1, 0});
    ASSERT_TRUE(square.hit());
    EXPECT_EQ(lit.pdfArea(square.geomID, square.primID, true, {-0.1f, -kBelow, 0.0f}), 0.0f);
}

// Only triangles with a lit patch have density slots: a hit on a reflecting triangle that lies
// wholly in shadow finds none (the shading then reads nothing at random; its MIS weight is 1
// either way, since such a triangle has density 0 everywhere).
TEST(LitSurfaces, AWhollyShadedTriangleHasNoDensitySlots) {
    scene::Scene s = emptyScene(glm::vec3(0.0f));
    const int grey = addMaterial(s, glm::vec3(kAlbedo)), black = addMaterial(s, glm::vec3(0.0f));
    scene::Primitive lit, shaded, card;
    lit.material = shaded.material = grey;
    card.material = black;
    addQuad(lit, {-1.5f, -kBelow, -0.5f}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});
    addQuad(shaded, {0.5f, -kBelow, -0.5f}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});
    addQuad(card, {0.25f, -0.5f, -0.75f}, {1.5f, 0, 0}, {0, 0, 1.5f}, {0, 1, 0});
    for (const scene::Primitive* p : {&lit, &shaded, &card})
        addInstance(s, *p);
    const pb::raytrace::RayScene rs(s);
    std::uint64_t shadow = 0;
    const LitSurfaces table(rs, sunFromAbove(1.0f), s.lights, 2, shadow);
    ASSERT_FALSE(table.empty());
    // Both triangles of each square: points either side of either diagonal.
    const glm::vec2 points[] = {{-1.3f, 0.1f}, {-0.7f, -0.1f}, {0.7f, 0.1f}, {1.3f, -0.1f}};
    unsigned prim[4];
    for (int k = 0; k < 4; ++k) {
        const float x = points[k].x;
        const glm::vec3 top(x, -kBelow, points[k].y);
        const pb::raytrace::RayHit h = rs.intersect(top + glm::vec3(0, 0.25f, 0), {0, -1, 0});
        ASSERT_TRUE(h.hit()) << x;
        prim[k] = h.primID;
        if (x < 0.0f) {
            EXPECT_GE(table.slotOfBarycentric(h.geomID, h.primID, false, h.u, h.v), 0) << x;
            EXPECT_GT(table.pdfArea(h.geomID, h.primID, false, top), 0.0f) << x;
        } else {
            EXPECT_EQ(table.slotOfBarycentric(h.geomID, h.primID, false, h.u, h.v), -1) << x;
            EXPECT_EQ(table.pdfArea(h.geomID, h.primID, false, top), 0.0f) << x;
        }
    }
    EXPECT_NE(prim[0], prim[1]);
    EXPECT_NE(prim[2], prim[3]);
}

TEST(LitSurfaces, NothingToSampleWithoutSunOrLights) {
    const scene::Scene s = squareScene(false);
    const pb::raytrace::RayScene rs(s);
    std::uint64_t shadow = 0;
    Scenario dark = sunFromAbove(1.0f);
    dark.sun.enabled = false;
    EXPECT_TRUE(LitSurfaces(rs, dark, s.lights, 2, shadow).empty());
    EXPECT_EQ(shadow, 0u);
    // A sun below the horizon lights no upward face: nothing either.
    Scenario below = sunFromAbove(1.0f);
    below.sun.toSun = glm::vec3(0, -1, 0);
    EXPECT_TRUE(LitSurfaces(rs, below, s.lights, 2, shadow).empty());
}

TEST(LitSurfaces, AProbeAboveASmallSunlitSquareConvergesWithoutBias) {
    const scene::Scene s = squareScene(false);
    const pb::raytrace::RayScene rs(s);
    const Scenario sc = sunFromAbove(2.0f);
    std::uint64_t shadow = 0;
    const LitSurfaces lit(rs, sc, s.lights, 2, shadow);
    // One round: 64 rays alone (the square covers ~1.6% of the sphere: about one ray) against
    // 64 rays + 64 lit-surface samples.
    const double raysAlone =
        meanRelativeError(litSurfaceSamplingProbeTexels(rs, s, sc, lit, 64, 0, 11), 2.0f);
    const double withSamples =
        meanRelativeError(litSurfaceSamplingProbeTexels(rs, s, sc, lit, 64, 64, 11), 2.0f);
    std::printf("one round, mean relative error of the texels facing the square: rays alone "
                "%.3f, with lit-surface samples %.3f\n", raysAlone, withSamples);
    EXPECT_LT(withSamples, 0.1);
    EXPECT_GT(raysAlone, 4 * withSamples);
    // Unbiased: the mean of 256 independent rounds with samples matches the quadrature to a
    // sixteenth of the single-round error (what averaging alone gives: 1 / sqrt(256)), give or
    // take the noise of that figure.
    const int rounds = 256;
    std::vector<double> mean(kIrradianceInteriorTexels * 3, 0.0);
    for (int r = 0; r < rounds; ++r) {
        const std::vector<float> t =
            litSurfaceSamplingProbeTexels(rs, s, sc, lit, 64, 64, 100 + std::uint64_t(r));
        for (std::size_t i = 0; i < mean.size(); ++i)
            mean[i] += t[i] / double(rounds);
    }
    std::vector<float> meanF(mean.begin(), mean.end());
    EXPECT_LT(meanRelativeError(meanF, 2.0f), 0.12 / 16.0 * 1.5);
}

namespace {
// One 3x2x3 volume over the square, one round of 64 rays.
BakeRequest squareBake(const scene::Scene& s, const Scenario& sc, int litSamples) {
    BakeRequest req;
    ProbeVolume v;
    v.name = "v";
    v.center = {0, -0.4f, 0};
    v.halfExtents = {0.6f, 0.5f, 0.6f};
    v.counts = {3, 2, 3};
    req.volumes = {v};
    req.scenarios = {sc};
    req.settings.raysPerProbe = 64;
    req.settings.noiseTarget = 0.0f;
    req.settings.litSamples = litSamples;
    return req;
}
} // namespace

TEST(LitSurfaces, BakesTheSameBytesOnAnyThreadCountAndChangeNothingWithoutLight) {
    const scene::Scene s = squareScene(true);
    BakeRequest req = squareBake(s, sunFromAbove(1.0f), 128);
    req.threads = 1;
    const ProbeSet one = bakeProbes(s, req);
    req.threads = 2;
    const ProbeSet two = bakeProbes(s, req);
    EXPECT_EQ(one.irradiance[0][0].texels, two.irradiance[0][0].texels);
    // The samples change a sunlit bake ...
    const ProbeSet without = bakeProbes(s, squareBake(s, sunFromAbove(1.0f), 0));
    EXPECT_NE(one.irradiance[0][0].texels, without.irradiance[0][0].texels);
    // ... and nothing where neither sun nor punctual lights shine (an emissive room).
    const scene::Scene glow = emissiveRoom(1.0f, 0.5f);
    Scenario dark;
    dark.sun.enabled = false;
    dark.sky.radiance = glm::vec3(0.0f);
    const ProbeSet a = bakeProbes(glow, squareBake(glow, dark, 0));
    const ProbeSet b = bakeProbes(glow, squareBake(glow, dark, 128));
    EXPECT_EQ(a.irradiance[0][0].texels, b.irradiance[0][0].texels);
}

TEST(LitSurfaces, SampleCountsOutsideTheRangeAreRefused) {
    const scene::Scene s = squareScene(false);
    for (int bad : {-1, 65537}) {
        try {
            bakeProbes(s, squareBake(s, sunFromAbove(1.0f), bad));
            ADD_FAILURE() << bad << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("--lit-samples"), std::string::npos) << e.what();
        }
    }
}
