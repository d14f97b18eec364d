// The CPU reference sampler (renderer/probes/ProbeSampler.h): GL-exact bilinear fetches,
// volume choice, edge fade, invalid probes, and degenerate input.
#include "probes/ProbeSampler.h"
#include "probes/Octahedral.h"
#include "probes/bake/RayDirections.h"

#include <cmath>
#include <cstring>
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

ProbeVolume probeSamplerBox(const std::string& name, glm::vec3 c, glm::vec3 h, glm::ivec3 n) {
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
    ProbeSet set = makeSet({probeSamplerBox("v", {1, 2, 3}, {2, 1, 2}, {4, 3, 5})},
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
    ProbeVolume v = probeSamplerBox("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2});
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
    ProbeSet set = makeSet({probeSamplerBox("v", {0, 0, 0}, {1, 1, 1}, {3, 3, 3})},
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
    ProbeSet set = makeSet({probeSamplerBox("v", {0, 0, 0}, {1, 1, 1}, {3, 3, 3})},
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
    ProbeVolume parent = probeSamplerBox("world", {0, 0, 0}, {4, 4, 4}, {3, 3, 3});
    ProbeVolume child = probeSamplerBox("room", {1, 0, 0}, {1, 1, 1}, {3, 3, 3});
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
    ProbeVolume v = probeSamplerBox("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2});
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
    ProbeVolume v = probeSamplerBox("v", {0, 0, 0}, {1, 0.5f, 0.5f}, {2, 1, 1});
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
    ProbeSet set = makeSet({probeSamplerBox("v", {0, 0, 0}, {1, 1, 1}, {1, 1, 1})},
                           [](glm::vec3, int) { return glm::vec3(4.0f); });
    ProbeSampler s(set, 0);
    IrradianceSample r = s.sample({0.3f, -0.2f, 0.9f}, {1, 0, 0}, {0, 0, 1});
    EXPECT_EQ(r.probes, 1);
    EXPECT_NEAR(r.irradiance.x, 4.0f, 1e-5f);
}

namespace {
// Two nested volumes (the root rotated, the child with a single-probe axis) with irregular
// data: random irradiance, random visibility (meanSq >= mean^2), relocated and invalid probes.
ProbeSet irregularSet() {
    ProbeVolume root = probeSamplerBox("world", {0.5f, 1, -1}, {3, 2, 2.5f}, {5, 4, 6});
    root.rotation = rotationFromEulerDegrees({10, 35, -5});
    ProbeVolume child = probeSamplerBox("room", {0.8f, 1.2f, -0.7f}, {1, 0.6f, 0.8f}, {3, 1, 4});
    child.parent = "world";
    std::uint64_t rng = 99;
    ProbeSet set = makeSet({root, child}, [&](glm::vec3 d, int) {
        return glm::vec3(uniformFloat(rng) * 4, uniformFloat(rng) + d.y, uniformFloat(rng));
    });
    for (ProbeTexture& vis : set.visibility)
        for (std::size_t i = 0; i < vis.texels.size(); i += 2) {
            float mean = uniformFloat(rng);
            vis.texels[i] = mean;
            vis.texels[i + 1] = mean * mean + 0.05f * uniformFloat(rng);
        }
    for (auto& states : set.states)
        for (ProbeState& st : states) {
            st.offset =
                (glm::vec3(uniformFloat(rng), uniformFloat(rng), uniformFloat(rng)) - 0.5f) * 0.3f;
            st.valid = uniformFloat(rng) > 0.15f;
        }
    return set;
}
} // namespace

TEST(ProbeSampler, BatchedLookupsEqualSingleLookupsBitForBit) {
    // sampleBatch pipelines the lookups (the bake's indirect term uses it): the results must
    // be exactly those of sample(), whatever the query: inside, in the fade region, outside,
    // degenerate (NaN, zero normal).
    ProbeSet set = irregularSet();
    ProbeSampler s(set, 0);
    std::uint64_t rng = 5;
    std::vector<SampleQuery> q;
    for (int i = 0; i < 3000; ++i) {
        glm::vec3 p(uniformFloat(rng) * 9 - 4, uniformFloat(rng) * 6 - 2,
                    uniformFloat(rng) * 8 - 5);
        q.push_back({p, randomUnit(rng), randomUnit(rng)});
    }
    q.push_back({{NAN, 0, 0}, {0, 1, 0}, {0, 1, 0}});
    q.push_back({{0.5f, 1, -1}, {0, 0, 0}, {0, 0, 0}});
    q.push_back({set.volumes[0].toWorld({-3, -2, -2.5f}), {0, 1, 0}, {1, 0, 0}}); // corner probe
    for (bool fade : {true, false}) {
        SampleOptions opt;
        opt.edgeFade = fade;
        std::vector<IrradianceSample> batch(q.size());
        s.sampleBatch(q.data(), q.size(), batch.data(), opt);
        int inside = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            IrradianceSample one = s.sample(q[i].pos, q[i].normal, q[i].view, opt);
            ASSERT_EQ(std::memcmp(&one.irradiance, &batch[i].irradiance, sizeof(glm::vec3)), 0)
                << "query " << i;
            ASSERT_EQ(one.weight, batch[i].weight) << "query " << i;
            ASSERT_EQ(one.volume, batch[i].volume) << "query " << i;
            ASSERT_EQ(one.probes, batch[i].probes) << "query " << i;
            inside += one.probes > 0;
        }
        EXPECT_GT(inside, 1000); // the queries exercised real lookups
    }
    s.sampleBatch(q.data(), 0, nullptr); // an empty batch is fine
    // sampleBatch runs the lookups in pairs: batches of every length from 1 to 9, so that
    // one ends on a pair and one on a lone lookup, over the last queries, where lookups that
    // end early (NaN, zero normal) sit beside full ones.
    int early = 0;
    for (std::size_t n = 1; n <= 9; ++n) {
        const SampleQuery* tail = q.data() + q.size() - n;
        std::vector<IrradianceSample> batch(n);
        s.sampleBatch(tail, n, batch.data());
        for (std::size_t i = 0; i < n; ++i) {
            IrradianceSample one = s.sample(tail[i].pos, tail[i].normal, tail[i].view);
            ASSERT_EQ(std::memcmp(&one.irradiance, &batch[i].irradiance, sizeof(glm::vec3)), 0)
                << "batch of " << n << ", query " << i;
            ASSERT_EQ(one.probes, batch[i].probes) << "batch of " << n << ", query " << i;
            early += one.probes == 0;
        }
    }
    EXPECT_GT(early, 0); // pairs with a lookup that ended early were among them
}

TEST(ProbeSampler, BatchedLookupsInRunsOfOneCellEqualSingleLookupsBitForBit) {
    // The bake sorts its lookups by cell (localityKey), and sampleBatch builds a cell's corner
    // probes once per run of lookups in it, with four lookups in flight. Runs of every length
    // from 1 to 9, in the root and in the child volume, must give exactly sample()'s results.
    ProbeSet set = irregularSet();
    ProbeSampler s(set, 0);
    std::uint64_t rng = 11;
    std::vector<SampleQuery> q;
    std::vector<std::uint32_t> keys;
    for (int run = 0; q.size() < 4000; ++run) {
        const glm::vec3 u(uniformFloat(rng), uniformFloat(rng), uniformFloat(rng));
        const ProbeVolume& in = set.volumes[run % 3 == 0 ? 1 : 0]; // a third in the child
        const glm::vec3 centre = in.toWorld((u * 2.0f - 1.0f) * in.halfExtents);
        const std::uint32_t key = s.localityKey(centre);
        for (int i = 0; i <= run % 9;) { // points of the same cell as the centre
            const glm::vec3 p = centre + (glm::vec3(uniformFloat(rng), uniformFloat(rng),
                                                    uniformFloat(rng)) - 0.5f) * 0.3f;
            if (s.localityKey(p) != key) continue;
            q.push_back({p, randomUnit(rng), randomUnit(rng)});
            keys.push_back(key);
            ++i;
        }
    }
    std::size_t runs = 1, inChild = 0;
    for (std::size_t i = 1; i < keys.size(); ++i)
        runs += keys[i] != keys[i - 1];
    for (std::uint32_t k : keys)
        inChild += k > std::uint32_t(set.volumes[0].probeCount());
    EXPECT_GT(runs, 500u); // many cells, in runs
    EXPECT_LT(runs, q.size() / 3);
    EXPECT_GT(inChild, 100u); // the child volume's cells too
    SampleOptions opt;
    opt.edgeFade = false;
    opt.bakeBias = true; // the bake's lookups
    // With and without the keys (which name the volume instead of selectVolume).
    std::vector<IrradianceSample> batch(q.size()), keyed(q.size());
    s.sampleBatch(q.data(), q.size(), batch.data(), opt);
    s.sampleBatch(q.data(), q.size(), keyed.data(), opt, keys.data());
    int lit = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
        IrradianceSample one = s.sample(q[i].pos, q[i].normal, q[i].view, opt);
        for (const IrradianceSample* b : {&batch[i], &keyed[i]}) {
            ASSERT_EQ(std::memcmp(&one.irradiance, &b->irradiance, sizeof(glm::vec3)), 0)
                << "query " << i;
            ASSERT_EQ(one.volume, b->volume) << "query " << i;
            ASSERT_EQ(one.probes, b->probes) << "query " << i;
        }
        lit += one.probes > 0;
    }
    EXPECT_GT(lit, 2000);
}

TEST(ProbeSampler, LocalityKeysNameTheCellOfThePoint) {
    ProbeSet set = irregularSet();
    ProbeSampler s(set, 0);
    const ProbeVolume& root = set.volumes[0];
    const ProbeVolume& child = set.volumes[1];
    EXPECT_EQ(s.localityKeyCount(), 1u + std::size_t(root.probeCount() + child.probeCount()));
    EXPECT_EQ(s.localityKey({50, 0, 0}), 0u);  // outside every volume
    EXPECT_EQ(s.localityKey({NAN, 0, 0}), 0u); // no volume either
    // Points inside one root cell (away from the child) share its key; the neighbouring cell
    // along each axis has another; the child's cells have keys of their own.
    const glm::vec3 cell = root.cellSize();
    auto rootPoint = [&](glm::ivec3 c, glm::vec3 f) {
        return root.toWorld(-root.halfExtents + (glm::vec3(c) + f) * cell);
    };
    std::uint32_t k = s.localityKey(rootPoint({3, 2, 4}, {0.1f, 0.2f, 0.3f}));
    EXPECT_NE(k, 0u);
    EXPECT_EQ(s.localityKey(rootPoint({3, 2, 4}, {0.9f, 0.8f, 0.7f})), k);
    EXPECT_NE(s.localityKey(rootPoint({2, 2, 4}, {0.5f, 0.5f, 0.5f})), k);
    EXPECT_NE(s.localityKey(rootPoint({3, 1, 4}, {0.5f, 0.5f, 0.5f})), k);
    EXPECT_NE(s.localityKey(rootPoint({3, 2, 3}, {0.5f, 0.5f, 0.5f})), k);
    std::uint32_t inChild = s.localityKey(child.toWorld({0.1f, 0.0f, 0.1f}));
    EXPECT_GT(inChild, std::uint32_t(root.probeCount()));
    EXPECT_LT(inChild, s.localityKeyCount());
    // The bake asks for a whole probe's keys in one call: each as alone, whatever the point
    // before it (outside every volume, NaN, another volume's).
    const std::vector<glm::vec3> points = {rootPoint({3, 2, 4}, {0.1f, 0.2f, 0.3f}),
                                           {50, 0, 0},
                                           rootPoint({3, 2, 4}, {0.9f, 0.8f, 0.7f}),
                                           child.toWorld({0.1f, 0.0f, 0.1f}),
                                           {NAN, 0, 0},
                                           rootPoint({2, 2, 4}, {0.5f, 0.5f, 0.5f})};
    std::vector<std::uint32_t> keys(points.size(), 12345u);
    s.localityKeys(points.data(), points.size(), keys.data());
    const std::vector<std::uint32_t> expected = {k, 0u, k, inChild, 0u,
                                                 s.localityKey(points[5])};
    EXPECT_EQ(keys, expected);
    EXPECT_NE(keys[5], k);
}
