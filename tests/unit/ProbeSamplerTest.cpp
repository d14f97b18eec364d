// The CPU reference sampler (renderer/probes/ProbeSampler.h): GL-exact bilinear fetches,
// volume choice, edge fade, invalid probes, and degenerate input.
#include "probes/ProbeSampler.h"
#include "probes/Octahedral.h"
#include "probes/RayDirections.h"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

using IrradianceFn = std::function<glm::vec3(const glm::vec3& localDir, int probe)>;

// A probe set with open visibility (nothing occludes: mean = meanSq = 1) and irradiance f.
ProbeSet makeSet(std::vector<ProbeVolume> vols, const IrradianceFn& f) {
    ProbeSet set;
    set.volumes = vols;
    set.scenarios.push_back({"day", {}, {}});
    set.irradiance.emplace_back();
    for (const ProbeVolume& v : vols) {
        set.states.emplace_back(size_t(v.probeCount()));
        ProbeTexture vis = ProbeTexture::make(visibilityShape(v.counts));
        for (float& x : vis.texels)
            x = 1.0f;
        set.visibility.push_back(vis);
        ProbeTexture irr = ProbeTexture::make(irradianceShape(v.counts));
        for (int p = 0; p < v.probeCount(); ++p) {
            glm::ivec3 c = v.probeCoords(p);
            for (int j = 0; j < kIrradianceInterior; ++j)
                for (int i = 0; i < kIrradianceInterior; ++i) {
                    glm::vec3 e = f(octTexelDirection(i, j, kIrradianceInterior), p);
                    float* t =
                        irr.at(c.x * kIrradianceTile + 1 + i, c.z * kIrradianceTile + 1 + j, c.y);
                    t[0] = e.x, t[1] = e.y, t[2] = e.z, t[3] = 1.0f;
                }
        }
        fillAllBorders(irr, kIrradianceInterior);
        set.irradiance[0].push_back(irr);
    }
    return set;
}

ProbeVolume box(const std::string& name, glm::vec3 c, glm::vec3 h, glm::ivec3 n) {
    ProbeVolume v;
    v.name = name;
    v.center = c;
    v.halfExtents = h;
    v.counts = n;
    return v;
}

glm::vec3 randomUnit(std::uint64_t& rng) {
    for (;;) {
        glm::vec3 d(uniformFloat(rng) * 2 - 1, uniformFloat(rng) * 2 - 1,
                    uniformFloat(rng) * 2 - 1);
        float l = glm::length(d);
        if (l > 0.1f && l <= 1.0f) return d / l;
    }
}

} // namespace

TEST(ProbeSampler, BilinearFetchMatchesGlLinear) {
    ProbeTexture t = ProbeTexture::make({4, 2, 1, 1});
    for (int i = 0; i < 8; ++i)
        t.texels[size_t(i)] = float(i * i);
    float out;
    bilinearFetch(t, 1.5f, 0.5f, 0, &out); // texel centre: exact
    EXPECT_FLOAT_EQ(out, 1.0f);
    bilinearFetch(t, 2.0f, 0.5f, 0, &out); // between texels 1 and 2
    EXPECT_FLOAT_EQ(out, 2.5f);
    bilinearFetch(t, 2.0f, 1.0f, 0, &out); // four-texel average: (1 + 4 + 25 + 36) / 4
    EXPECT_FLOAT_EQ(out, 16.5f);
    bilinearFetch(t, 0.1f, 0.1f, 0, &out); // clamp to edge
    EXPECT_FLOAT_EQ(out, 0.0f);
}

TEST(ProbeSampler, UniformIrradianceIsReturnedEverywhereInside) {
    ProbeSet set = makeSet({box("v", {1, 2, 3}, {2, 1, 2}, {4, 3, 5})},
                           [](glm::vec3, int) { return glm::vec3(float(M_PI)); });
    ProbeSampler s(set, 0);
    std::uint64_t rng = 3;
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 p =
            glm::vec3(1, 2, 3) + glm::vec3(uniformFloat(rng) * 4 - 2, uniformFloat(rng) * 2 - 1,
                                           uniformFloat(rng) * 4 - 2);
        IrradianceSample r = s.sample(p, randomUnit(rng), randomUnit(rng));
        ASSERT_EQ(r.volume, 0);
        ASSERT_GT(r.probes, 0);
        EXPECT_NEAR(r.irradiance.x, float(M_PI), 1e-5f);
        EXPECT_FLOAT_EQ(r.weight, 1.0f);
    }
}

TEST(ProbeSampler, NormalIsLookedUpInTheVolumesLocalFrame) {
    // Irradiance = a function of the LOCAL direction; the volume is rotated. A world normal
    // that is the rotated centre of texel (i, j) must read exactly that texel's value.
    auto f = [](glm::vec3 d, int) { return glm::vec3(3.0f + d.x + 2.0f * d.y - 0.5f * d.z); };
    ProbeVolume v = box("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2});
    v.rotation = rotationFromEulerDegrees({20, 90, -35});
    ProbeSet set = makeSet({v}, f);
    ProbeSampler s(set, 0);
    ProbeVolume plain = v;
    plain.rotation = glm::quat(1, 0, 0, 0);
    ProbeSet plainSet = makeSet({plain}, f);
    ProbeSampler unrotated(plainSet, 0);
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i) {
            glm::vec3 local = octTexelDirection(i, j, kIrradianceInterior);
            glm::vec3 n = v.rotation * local;
            EXPECT_NEAR(s.sample(v.toWorld({0.1f, 0.2f, -0.3f}), n, n).irradiance.x, f(local, 0).x,
                        1e-4f);
        }
    // Any normal: the rotated volume equals the unrotated one fed the local normal.
    std::uint64_t rng = 11;
    for (int i = 0; i < 500; ++i) {
        glm::vec3 n = randomUnit(rng), view = randomUnit(rng), p(0.3f, -0.6f, 0.2f);
        glm::vec3 ln = glm::conjugate(v.rotation) * n, lv = glm::conjugate(v.rotation) * view;
        EXPECT_NEAR(s.sample(v.toWorld(p), n, view).irradiance.x,
                    unrotated.sample(p, ln, lv).irradiance.x, 1e-4f);
    }
}

TEST(ProbeSampler, OutsideEveryVolumeGivesZeroWeight) {
    ProbeSet set = makeSet({box("v", {0, 0, 0}, {1, 1, 1}, {3, 3, 3})},
                           [](glm::vec3, int) { return glm::vec3(1.0f); });
    ProbeSampler s(set, 0);
    IrradianceSample r = s.sample({5, 0, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_EQ(r.volume, -1);
    EXPECT_EQ(r.weight, 0.0f);
    EXPECT_EQ(r.irradiance, glm::vec3(0.0f));
    // NaN input: no volume, no NaN out.
    IrradianceSample n = s.sample({NAN, 0, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_EQ(n.weight, 0.0f);
    EXPECT_FALSE(std::isnan(n.irradiance.x));
}

TEST(ProbeSampler, RootVolumesFadeOutsideTheirBox) {
    ProbeSet set = makeSet({box("v", {0, 0, 0}, {1, 1, 1}, {3, 3, 3})},
                           [](glm::vec3, int) { return glm::vec3(2.0f); });
    ProbeSampler s(set, 0);
    // cell = 1, fade width 0.5: at x = 1.25 half faded.
    IrradianceSample r = s.sample({1.25f, 0, 0}, {1, 0, 0}, {1, 0, 0});
    EXPECT_EQ(r.volume, 0);
    EXPECT_NEAR(r.weight, 0.5f, 1e-5f);
    EXPECT_NEAR(r.irradiance.x, 1.0f, 1e-5f);
    SampleOptions noFade;
    noFade.edgeFade = false;
    EXPECT_NEAR(s.sample({1.25f, 0, 0}, {1, 0, 0}, {1, 0, 0}, noFade).irradiance.x, 2.0f, 1e-5f);
    EXPECT_EQ(s.sample({1.51f, 0, 0}, {1, 0, 0}, {1, 0, 0}).volume, -1);
}

TEST(ProbeSampler, SmallestContainingVolumeWins) {
    ProbeVolume parent = box("world", {0, 0, 0}, {4, 4, 4}, {3, 3, 3});
    ProbeVolume child = box("room", {1, 0, 0}, {1, 1, 1}, {3, 3, 3});
    child.parent = "world";
    ProbeSet set = makeSet({parent, child}, [](glm::vec3, int) { return glm::vec3(1.0f); });
    for (float& x : set.irradiance[0][1].texels)
        x = 5.0f; // the child reads 5
    ProbeSampler s(set, 0);
    EXPECT_EQ(s.sample({1.5f, 0, 0}, {0, 1, 0}, {0, 1, 0}).volume, 1);
    EXPECT_NEAR(s.sample({1.5f, 0, 0}, {0, 1, 0}, {0, 1, 0}).irradiance.x, 5.0f, 1e-5f);
    // Children have no fade region: just outside the child the parent takes over.
    EXPECT_EQ(s.sample({2.05f, 0, 0}, {0, 1, 0}, {0, 1, 0}).volume, 0);
}

TEST(ProbeSampler, InvalidProbesAreExcludedAndAllInvalidGivesNoNaN) {
    ProbeVolume v = box("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2});
    ProbeSet set = makeSet({v}, [](glm::vec3, int p) { return glm::vec3(p == 0 ? 100.0f : 1.0f); });
    set.states[0][0].valid = false;
    ProbeSampler s(set, 0);
    IrradianceSample r = s.sample({-0.9f, -0.9f, -0.9f}, {0, 1, 0}, {0, 1, 0});
    EXPECT_EQ(r.probes, 7);
    EXPECT_NEAR(r.irradiance.x, 1.0f, 1e-5f);
    for (ProbeState& st : set.states[0])
        st.valid = false;
    ProbeSampler none(set, 0);
    IrradianceSample z = none.sample({0, 0, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_EQ(z.volume, 0);
    EXPECT_EQ(z.probes, 0);
    EXPECT_EQ(z.weight, 0.0f);
    EXPECT_EQ(z.irradiance, glm::vec3(0.0f));
}

TEST(ProbeSampler, ChebyshevVisibilityDownweightsOccludedProbes) {
    // Probe 1 (x = +1) "sees" a wall at 10% of max distance in every direction: a point
    // beyond that wall should get (almost) only probe 0's irradiance.
    ProbeVolume v = box("v", {0, 0, 0}, {1, 0.5f, 0.5f}, {2, 1, 1});
    ProbeSet set = makeSet({v}, [](glm::vec3, int p) { return glm::vec3(p == 0 ? 1.0f : 9.0f); });
    ProbeTexture& vis = set.visibility[0];
    for (int y = 0; y < kVisibilityTile; ++y)
        for (int x = 0; x < kVisibilityTile; ++x) {
            float* t = vis.at(kVisibilityTile + x, y, 0);
            t[0] = 0.1f;
            t[1] = 0.01f;
        }
    ProbeSampler s(set, 0);
    IrradianceSample r = s.sample({-0.2f, 0, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_LT(r.irradiance.x, 1.2f);
    EXPECT_GT(r.irradiance.x, 0.99f);
}

TEST(ProbeSampler, SingleProbeAxesAndOneProbeVolumes) {
    ProbeSet set = makeSet({box("v", {0, 0, 0}, {1, 1, 1}, {1, 1, 1})},
                           [](glm::vec3, int) { return glm::vec3(4.0f); });
    ProbeSampler s(set, 0);
    IrradianceSample r = s.sample({0.3f, -0.2f, 0.9f}, {1, 0, 0}, {0, 0, 1});
    EXPECT_EQ(r.probes, 1);
    EXPECT_NEAR(r.irradiance.x, 4.0f, 1e-5f);
}
