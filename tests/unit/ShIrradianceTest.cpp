// The SH technique's probes: the projection and the cosine-lobe lookup against closed forms,
// the bake's SH in the probe file (and older files reading as "no SH"), and the CPU SH
// sampler's leak modes.
#include "probes/sh/ShIrradiance.h"
#include "OlderProbeFile.h"
#include "ProbeTestScenes.h"
#include "SunlitFloorBake.h"
#include "core/Error.h"
#include "probes/sh/ShSampler.h"
#include "probes/bake/Baker.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

constexpr float kShIrradiancePi = 3.14159265f;

std::vector<glm::vec3> radianceOf(const std::vector<glm::vec3>& dirs,
                                  glm::vec3 (*f)(const glm::vec3&)) {
    std::vector<glm::vec3> out;
    for (const glm::vec3& d : dirs)
        out.push_back(f(d));
    return out;
}

glm::vec3 clampedCosineUp(const glm::vec3& d) {
    return glm::vec3(std::max(0.0f, d.z));
}

ProbeSet shIrradianceSmallBake() {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    return bakeProbes(s, pb::test::sunlitFloorRequest(s));
}

// The same file as version 5 wrote it: no SH record, version 5, size and checksum redone.
std::vector<std::uint8_t> asVersion5(std::vector<std::uint8_t> bytes, const ProbeSet& set) {
    std::size_t shBytes = 1 + set.probeCount();
    for (std::size_t s = 0; s < set.sh.size(); ++s)
        for (const ProbeVolume& v : set.volumes)
            shBytes += std::size_t(v.probeCount()) * 9 * 12;
    shBytes += 1 + 8; // and version 8's free-space record after it
    return pb::test::asOlderProbeFile(std::move(bytes), shBytes, 5);
}

} // namespace

TEST(ShIrradiance, ConstantRadianceGivesPiTimesRadianceEverywhere) {
    const auto dirs = shProjectionDirections(kShProjectionDirections);
    const ShCoefficients c =
        projectRadiance(dirs, std::vector<glm::vec3>(dirs.size(), glm::vec3(1, 2, 3)));
    for (const glm::vec3& n :
         {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::normalize(glm::vec3(-1, 2, -3))})
        for (int count : {kShL1Coefficients, kShL2Coefficients}) {
            const glm::vec3 e = shIrradiance(c.data(), n, count);
            EXPECT_NEAR(e.x, kShIrradiancePi * 1, 1e-3f);
            EXPECT_NEAR(e.y, kShIrradiancePi * 2, 2e-3f);
            EXPECT_NEAR(e.z, kShIrradiancePi * 3, 3e-3f);
        }
}

TEST(ShIrradiance, ClampedCosineRadianceMatchesTheBandLimitedClosedForm) {
    // L = max(0, d.z) has zonal coefficients A_l Y_l0(z); at n = z the convolved series is
    // sum_l A_l^2 (2l+1) / 4pi per band, and the exact irradiance is the integral of cos^2
    // over the hemisphere, 2pi/3.
    const auto dirs = shProjectionDirections(kShProjectionDirections);
    const ShCoefficients c = projectRadiance(dirs, radianceOf(dirs, clampedCosineUp));
    float band[3];
    for (int l = 0; l < 3; ++l)
        band[l] = kShBandA[l] * kShBandA[l] * float(2 * l + 1) / (4 * kShIrradiancePi);
    const glm::vec3 up(0, 0, 1);
    EXPECT_NEAR(shIrradiance(c.data(), up, 4).x, band[0] + band[1], 2e-3f);
    EXPECT_NEAR(shIrradiance(c.data(), up, 9).x, band[0] + band[1] + band[2], 2e-3f);
    EXPECT_NEAR(shIrradiance(c.data(), up, 9).x, 2 * kShIrradiancePi / 3,
                0.01f * 2 * kShIrradiancePi / 3);
}

TEST(ShIrradiance, L2ReconstructsALobeBetterThanL1) {
    const auto dirs = shProjectionDirections(kShProjectionDirections);
    const ShCoefficients c = projectRadiance(dirs, radianceOf(dirs, clampedCosineUp));
    // Exact irradiance of the clamped-cosine radiance, by quadrature over the same directions.
    double errL1 = 0, errL2 = 0;
    const auto normals = shProjectionDirections(64);
    for (const glm::vec3& n : normals) {
        double exact = 0;
        for (const glm::vec3& d : dirs)
            exact += std::max(0.0f, d.z) * std::max(0.0f, glm::dot(d, n));
        exact *= 4 * kShIrradiancePi / double(dirs.size());
        errL1 += std::abs(shIrradiance(c.data(), n, 4).x - exact);
        errL2 += std::abs(shIrradiance(c.data(), n, 9).x - exact);
    }
    EXPECT_LT(errL2, 0.5 * errL1) << "L1 " << errL1 / 64 << " L2 " << errL2 / 64;
}

TEST(ShIrradiance, BakeStoresShThatAgreesWithTheOctahedralIrradiance) {
    const ProbeSet set = shIrradianceSmallBake();
    ASSERT_TRUE(set.hasSh());
    ASSERT_EQ(set.sh.size(), set.irradiance.size());
    const ProbeVolume& v = set.volumes[0];
    ASSERT_EQ(set.sh[0][0].size(), std::size_t(v.probeCount()) * 9);
    // A probe's L2 irradiance towards the sky and towards the floor is close to its map's.
    for (int p = 0; p < v.probeCount(); ++p) {
        const glm::ivec3 c = v.probeCoords(p);
        for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
            const glm::vec2 t = tileCoord(c, n, kIrradianceInterior);
            float map[4];
            bilinearFetch(set.irradiance[0][0], t.x, t.y, c.y, map);
            const glm::vec3 sh = shIrradiance(&set.sh[0][0][size_t(p) * 9], n, 9);
            EXPECT_NEAR(sh.y, map[1], 0.1f * map[1] + 1e-3f) << "probe " << p;
        }
    }
}

TEST(ShIrradiance, FileRoundTripKeepsShAndVersion5ReadsAsNoSh) {
    const ProbeSet set = shIrradianceSmallBake();
    const std::vector<std::uint8_t> bytes = serializeProbeSet(set);
    const ProbeSet back = parseProbeSet(bytes, "p.pbp");
    ASSERT_TRUE(back.hasSh());
    for (std::size_t s = 0; s < set.sh.size(); ++s)
        EXPECT_EQ(std::memcmp(back.sh[s][0].data(), set.sh[s][0].data(),
                              set.sh[s][0].size() * sizeof(glm::vec3)),
                  0);
    const ProbeSet old = parseProbeSet(asVersion5(bytes, set), "old.pbp");
    EXPECT_FALSE(old.hasSh());
    EXPECT_EQ(old.irradiance[0][0].texels, back.irradiance[0][0].texels);
    try {
        ShSampler sampler(old, 0, "old.pbp");
        FAIL() << "no error";
    } catch (const pb::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("old.pbp"), std::string::npos) << m;
        EXPECT_NE(m.find("re-bake"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

TEST(ShSampler, NudgeGivesEveryInvalidCornerZeroWeight) {
    for (int mask = 1; mask < 256; ++mask)
        for (const glm::vec3& start :
             {glm::vec3(0.5f), glm::vec3(0.1f, 0.7f, 0.3f), glm::vec3(0.9f, 0.2f, 0.6f)}) {
            glm::vec3 f = start;
            ASSERT_TRUE(nudgeToValid(f, std::uint8_t(mask)));
            float valid = 0;
            for (int c = 0; c < 8; ++c) {
                float w = 1;
                for (int a = 0; a < 3; ++a)
                    w *= (c >> a) & 1 ? f[a] : 1 - f[a];
                if (mask & (1 << c))
                    valid += w;
                else
                    EXPECT_EQ(w, 0.0f) << "mask " << mask << " corner " << c;
            }
            EXPECT_NEAR(valid, 1.0f, 1e-6f);
        }
    glm::vec3 f(0.3f);
    EXPECT_FALSE(nudgeToValid(f, 0));
}

TEST(ShSampler, ValidProbesInterpolateTheirIrradianceAndModesAgreeWithoutInvalidProbes) {
    ProbeSet set = shIrradianceSmallBake();
    for (auto& s : set.states[0])
        s.valid = true, s.insideAtLattice = false;
    const ShSampler sampler(set, 0, "p.pbp");
    const glm::vec3 n(0, 1, 0);
    // At a probe's own position (no bias along a normal without view offset is impossible, so
    // compare modes instead): with every probe valid the three modes are the same lookup.
    for (const glm::vec3& pos : {glm::vec3(0.3f, 0.5f, -0.7f), glm::vec3(-1.2f, 1.4f, 1.1f)}) {
        ShSampleOptions o;
        o.coefficients = 9;
        const glm::vec3 none = sampler.sample(pos, n, n, o).irradiance;
        o.leak = ShLeak::Weight;
        const glm::vec3 weight = sampler.sample(pos, n, n, o).irradiance;
        o.leak = ShLeak::ValidityMask;
        const glm::vec3 mask = sampler.sample(pos, n, n, o).irradiance;
        EXPECT_GT(none.y, 0.0f);
        EXPECT_NEAR(weight.y, none.y, 1e-5f * none.y);
        EXPECT_NEAR(mask.y, none.y, 1e-5f * none.y);
    }
}

TEST(ShSampler, WeightAndMaskIgnoreAnInvalidProbesLight) {
    ProbeSet set = shIrradianceSmallBake();
    for (auto& s : set.states[0])
        s.valid = true, s.insideAtLattice = false;
    // Make one probe invalid and give it absurd light: `none` sees it, the others must not.
    const ProbeVolume& v = set.volumes[0];
    const int bad = v.probeIndex({1, 0, 1});
    set.states[0][size_t(bad)].valid = false;
    set.sh[0][0][size_t(bad) * 9] = glm::vec3(1e4f);
    const ShSampler sampler(set, 0, "p.pbp");
    const glm::vec3 pos = v.toWorld(v.gridLocal({1, 0, 1}) * 0.8f + v.gridLocal({2, 1, 2}) * 0.2f);
    const glm::vec3 n(0, 1, 0);
    ShSampleOptions o;
    const float none = sampler.sample(pos, n, n, o).irradiance.y;
    o.leak = ShLeak::Weight;
    const float weight = sampler.sample(pos, n, n, o).irradiance.y;
    o.leak = ShLeak::ValidityMask;
    const float mask = sampler.sample(pos, n, n, o).irradiance.y;
    EXPECT_GT(none, 100.0f);
    EXPECT_LT(weight, 100.0f);
    EXPECT_LT(mask, 100.0f);
    EXPECT_GT(weight, 0.0f);
    EXPECT_GT(mask, 0.0f);
}
