// The truth's stratified samples (truth/ScrambledSobol.h): Sobol's first two dimensions form
// nets, the hash scrambling keeps them nets, the index shuffle stays inside its block, each
// dimension pair of a batch is stratified and the pairs differ, and the path tracer's reported
// noise matches the spread of its image across seeds (stratified samples must not make the
// variance estimate lie).
#include "scene/SceneBuilder.h"
#include "truth/PathTracer.h"
#include "truth/ScrambledSobol.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <vector>

using namespace pb;
using truth::owenScramble;

namespace {

// True when the points (fractions of 2^32) form a (0,k,2)-net: for every split of k bits
// into a bits of x and k-a bits of y, each elementary box holds exactly one point.
bool isNet(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& points, int k) {
    if (points.size() != (std::size_t(1) << k)) return false;
    for (int a = 0; a <= k; ++a) {
        std::set<std::uint64_t> boxes;
        for (auto [x, y] : points) {
            const std::uint64_t bx = a == 0 ? 0 : x >> (32 - a);
            const std::uint64_t by = a == k ? 0 : y >> (32 - (k - a));
            boxes.insert((bx << 32) | by);
        }
        if (boxes.size() != points.size()) return false;
    }
    return true;
}

std::uint32_t fixedPoint(float u) { return std::uint32_t(double(u) * 4294967296.0); }

} // namespace

TEST(ScrambledSobol, ReverseBitsMirrorsTheWord) {
    EXPECT_EQ(truth::reverseBits32(1u), 0x80000000u);
    EXPECT_EQ(truth::reverseBits32(0x0000000Fu), 0xF0000000u);
    EXPECT_EQ(truth::reverseBits32(0x12345678u), 0x1E6A2C48u);
    EXPECT_EQ(truth::reverseBits32(truth::reverseBits32(0xDEADBEEFu)), 0xDEADBEEFu);
}

TEST(ScrambledSobol, TheFirstTwoDimensionsFormNetsAndScramblingKeepsThem) {
    // Sobol's dimension 1 starts 0, 1/2, 3/4, 1/4 (direction numbers of x + 1).
    EXPECT_EQ(truth::sobolDimension1(0), 0u);
    EXPECT_EQ(truth::sobolDimension1(1), 0x80000000u);
    EXPECT_EQ(truth::sobolDimension1(2), 0xC0000000u);
    EXPECT_EQ(truth::sobolDimension1(3), 0x40000000u);
    for (int k : {4, 7, 10}) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> plain, scrambled, offset;
        for (std::uint32_t i = 0; i < (1u << k); ++i) {
            plain.emplace_back(truth::sobolDimension0(i), truth::sobolDimension1(i));
            scrambled.emplace_back(owenScramble(truth::sobolDimension0(i), 17u),
                                   owenScramble(truth::sobolDimension1(i), 0x9e3779b9u));
            const std::uint32_t j = (5u << k) + i; // any aligned block of 2^k points
            offset.emplace_back(truth::sobolDimension0(j), truth::sobolDimension1(j));
        }
        EXPECT_TRUE(isNet(plain, k)) << k;
        EXPECT_TRUE(isNet(scrambled, k)) << k;
        EXPECT_TRUE(isNet(offset, k)) << k;
    }
    // A plain XOR or an unstructured hash would not do; this one depends on the seed.
    EXPECT_NE(owenScramble(0x40000000u, 1u), owenScramble(0x40000000u, 2u));
}

TEST(ScrambledSobol, TheIndexShuffleStaysInsideItsBlock) {
    for (std::uint32_t seed : {0u, 1u, 12345u, 0xfeedbeefu}) {
        std::set<std::uint32_t> seen, blocks;
        for (std::uint32_t i = 0; i < 256; ++i) {
            const std::uint32_t j = owenScramble(i, seed);
            seen.insert(j);
            blocks.insert(j >> 8);
        }
        EXPECT_EQ(seen.size(), 256u) << seed; // one to one
        EXPECT_EQ(blocks.size(), 1u) << seed; // one aligned block of 256
    }
}

TEST(ScrambledSobol, EachPairOfABatchIsStratifiedAndThePairsDiffer) {
    constexpr int k = 6; // 64 samples per batch
    const std::uint32_t n = truth::kBatches << k;
    for (int batch = 0; batch < truth::kBatches; ++batch) {
        std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> pairs(5);
        for (std::uint32_t s = std::uint32_t(batch); s < n; s += truth::kBatches) {
            truth::PathSampler sampler(3, 1234, s);
            for (auto& pair : pairs) {
                float u, v;
                sampler.next2D(u, v);
                ASSERT_GE(u, 0.0f);
                ASSERT_LT(u, 1.0f);
                ASSERT_LT(v, 1.0f);
                pair.emplace_back(fixedPoint(u), fixedPoint(v));
            }
        }
        for (std::size_t d = 0; d < pairs.size(); ++d) {
            // Up to the 24 bits a float in [0, 1) keeps, which 2^6 boxes never reach.
            EXPECT_TRUE(isNet(pairs[d], k)) << "batch " << batch << " pair " << d;
            if (d > 0) {
                EXPECT_NE(pairs[d], pairs[d - 1]) << "pair " << d;
            }
        }
    }
    // Another pixel draws other points.
    float a, b, c, d;
    truth::PathSampler(3, 1234, 0).next2D(a, b);
    truth::PathSampler(3, 1235, 0).next2D(c, d);
    EXPECT_TRUE(a != c || b != d);
}

TEST(ScrambledSobol, ThePathTracersNoiseMatchesTheSpreadAcrossSeeds) {
    // A sunlit floor under a roof with a hole: the floor's light comes from a patch a bounce
    // finds or misses, the discontinuous integrand stratification helps most with.
    scene::Scene s;
    s.name = "patch";
    s.sky.radiance = glm::vec3(0.0f);
    s.sun.enabled = true;
    s.sun.toSun = glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f));
    s.sun.intensity = 3.0f;
    s.sun.color = glm::vec3(1.0f);
    scene::SceneBuilder b(s);
    int m = b.material("m", glm::vec3(0.7f), glm::vec3(0.0f));
    b.box("floor", glm::vec3(-2.0f, -0.1f, -2.0f), glm::vec3(2.0f, 0.0f, 2.0f), m);
    b.box("roofA", glm::vec3(-2.0f, 1.0f, -2.0f), glm::vec3(-0.3f, 1.1f, 2.0f), m);
    b.box("roofB", glm::vec3(0.3f, 1.0f, -2.0f), glm::vec3(2.0f, 1.1f, 2.0f), m);
    const scene::View view{"down", {0.0f, 0.8f, 0.0f}, {0.6f, -0.8f, 0.0f}, 70.0f};
    truth::TruthSettings ts;
    ts.width = ts.height = 12;
    ts.spp = 32;
    constexpr int kSeeds = 12;
    std::vector<std::vector<double>> lum(kSeeds);
    double reported = 0.0;
    for (int seed = 0; seed < kSeeds; ++seed) {
        ts.seed = std::uint64_t(seed + 1);
        const truth::TruthResult r = truth::renderTruth(s, view, ts);
        ASSERT_TRUE(r.noise.varianceKnown);
        // pixelRelativeStandardError^2 * mean^2 = the mean over pixels of each pixel mean's variance.
        reported += std::pow(r.noise.pixelRelativeStandardError * r.noise.meanLuminance, 2.0) / kSeeds;
        for (std::size_t p = 0; p < r.hdr.pixels.size(); p += 4)
            lum[size_t(seed)].push_back(0.2126 * r.hdr.pixels[p] + 0.7152 * r.hdr.pixels[p + 1] +
                                        0.0722 * r.hdr.pixels[p + 2]);
    }
    double observed = 0.0;
    const std::size_t P = lum[0].size();
    for (std::size_t p = 0; p < P; ++p) {
        double mean = 0.0, sq = 0.0;
        for (int k = 0; k < kSeeds; ++k) mean += lum[size_t(k)][p] / kSeeds;
        for (int k = 0; k < kSeeds; ++k) sq += std::pow(lum[size_t(k)][p] - mean, 2.0);
        observed += sq / (kSeeds - 1) / double(P);
    }
    ASSERT_GT(observed, 0.0);
    EXPECT_NEAR(reported / observed, 1.0, 0.35) << "reported " << reported << " observed " << observed;
}
