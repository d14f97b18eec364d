// Octahedral mapping, texel convention and the mirrored borders that make bilinear
// filtering seamless (renderer/probes/Octahedral.h).
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/RayDirections.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Where a point just outside the square lands on the octahedron: reflect across the edge it
// crossed and negate the other coordinate.
glm::vec2 wrapUv(glm::vec2 uv) {
    if (uv.y < -1.0f) uv = {-uv.x, -2.0f - uv.y};
    if (uv.y > 1.0f) uv = {-uv.x, 2.0f - uv.y};
    if (uv.x < -1.0f) uv = {-2.0f - uv.x, -uv.y};
    if (uv.x > 1.0f) uv = {2.0f - uv.x, -uv.y};
    return uv;
}

} // namespace

TEST(Octahedral, SixAxesMapToTheDocumentedPoints) {
    EXPECT_EQ(octEncode({0, 1, 0}), glm::vec2(0, 0));
    EXPECT_EQ(octEncode({1, 0, 0}), glm::vec2(1, 0));
    EXPECT_EQ(octEncode({-1, 0, 0}), glm::vec2(-1, 0));
    EXPECT_EQ(octEncode({0, 0, 1}), glm::vec2(0, 1));
    EXPECT_EQ(octEncode({0, 0, -1}), glm::vec2(0, -1));
    EXPECT_EQ(octEncode({0, -1, 0}), glm::vec2(1, 1)); // -Y folds to the corners
    for (glm::vec3 axis : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                           glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
        expectNear(octDecode(octEncode(axis)), axis, 1e-6f);
    for (glm::vec2 corner :
         {glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)})
        expectNear(octDecode(corner), {0, -1, 0}, 1e-6f);
}

TEST(Octahedral, RoundTripsRandomAndFoldEdgeDirections) {
    std::uint64_t rng = 7;
    for (int i = 0; i < 20000; ++i) {
        glm::vec3 d(uniformFloat(rng) * 2 - 1, uniformFloat(rng) * 2 - 1,
                    uniformFloat(rng) * 2 - 1);
        if (glm::length(d) < 1e-3f) continue;
        d = glm::normalize(d);
        glm::vec2 e = octEncode(d);
        ASSERT_LE(std::abs(e.x), 1.0f);
        ASSERT_LE(std::abs(e.y), 1.0f);
        expectNear(octDecode(e), d, 2e-6f);
    }
    // The equator (y = 0) is the fold between the hemispheres: |u| + |v| = 1 exactly.
    for (int i = 0; i < 360; ++i) {
        float a = glm::radians(float(i));
        glm::vec3 d(std::cos(a), 0.0f, std::sin(a));
        glm::vec2 e = octEncode(d);
        EXPECT_NEAR(std::abs(e.x) + std::abs(e.y), 1.0f, 1e-6f);
        expectNear(octDecode(e), d, 2e-6f);
        // Just below the equator lands just outside the diamond, continuously.
        glm::vec3 below = glm::normalize(glm::vec3(d.x, -1e-4f, d.z));
        EXPECT_LT(glm::distance(octEncode(below), e), 1e-3f);
    }
}

TEST(Octahedral, TexelCentresAreUnitAndMapBackToTheirTexel) {
    for (int n : {kIrradianceInterior, kVisibilityInterior})
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                EXPECT_NEAR(glm::length(octTexelDirection(i, j, n)), 1.0f, 1e-6f);
                glm::vec2 c = octInteriorCoord(octTexelDirection(i, j, n), n);
                EXPECT_NEAR(c.x, float(i) + 0.5f, 1e-4f);
                EXPECT_NEAR(c.y, float(j) + 0.5f, 1e-4f);
            }
}

TEST(Octahedral, BorderTexelsEqualTheirMirroredNeighbours) {
    for (int n : {kIrradianceInterior, kVisibilityInterior}) {
        const int tile = n + 2;
        std::vector<float> t(size_t(tile * tile), -1.0f);
        for (int y = 1; y <= n; ++y)
            for (int x = 1; x <= n; ++x)
                t[size_t(y * tile + x)] = float(y * 100 + x);
        fillOctahedralBorder(t.data(), tile, 1, n);
        for (int y = 0; y < tile; ++y)
            for (int x = 0; x < tile; ++x) {
                if (x >= 1 && x <= n && y >= 1 && y <= n) continue;
                // The border texel's centre, outside the square, wrapped onto the octahedron,
                // must be the centre of the interior texel it copies.
                glm::vec2 uv((2.0f * float(x - 1) + 1.0f) / float(n) - 1.0f,
                             (2.0f * float(y - 1) + 1.0f) / float(n) - 1.0f);
                glm::vec2 w = wrapUv(uv);
                int sx = int(std::lround(((w.x + 1.0f) * float(n) - 1.0f) / 2.0f)) + 1;
                int sy = int(std::lround(((w.y + 1.0f) * float(n) - 1.0f) / 2.0f)) + 1;
                ASSERT_GE(sx, 1);
                ASSERT_LE(sx, n);
                ASSERT_GE(sy, 1);
                ASSERT_LE(sy, n);
                EXPECT_EQ(t[size_t(y * tile + x)], t[size_t(sy * tile + sx)])
                    << "border texel (" << x << "," << y << ") of a " << tile << "-texel tile";
            }
    }
}

TEST(Octahedral, BilinearFilteringIsSeamlessAcrossFolds) {
    // A smooth function of direction stored in one tile with borders, then sampled the way
    // GL does: directions straddling a fold edge must read (almost) the same value.
    ProbeTexture tex = ProbeTexture::make(irradianceShape({1, 1, 1}));
    auto f = [](glm::vec3 d) { return 2.0f + d.x + 0.5f * d.y - 0.75f * d.z; };
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i) {
            float* p = tex.at(i + 1, j + 1, 0);
            p[0] = p[1] = p[2] = f(octTexelDirection(i, j, kIrradianceInterior));
            p[3] = 1.0f;
        }
    fillAllBorders(tex, kIrradianceInterior);
    auto sample = [&](glm::vec3 d) {
        glm::vec2 c = tileCoord({0, 0, 0}, d, kIrradianceInterior);
        float out[4];
        bilinearFetch(tex, c.x, c.y, 0, out);
        return out[0];
    };
    float maxJump = 0.0f, maxErr = 0.0f;
    for (int i = 0; i < 720; ++i) {
        float a = glm::radians(float(i) * 0.5f);
        // Across the equator fold (upper vs lower hemisphere) ...
        glm::vec3 up = glm::normalize(glm::vec3(std::cos(a), 1e-4f, std::sin(a)));
        glm::vec3 down = glm::normalize(glm::vec3(std::cos(a), -1e-4f, std::sin(a)));
        maxJump = std::max(maxJump, std::abs(sample(up) - sample(down)));
        // ... and across the square's outer edges (lower hemisphere, u or v = +-1).
        glm::vec3 l1 = glm::normalize(glm::vec3(1e-4f, -std::abs(std::cos(a)) - 0.1f, std::sin(a)));
        glm::vec3 l2 =
            glm::normalize(glm::vec3(-1e-4f, -std::abs(std::cos(a)) - 0.1f, std::sin(a)));
        maxJump = std::max(maxJump, std::abs(sample(l1) - sample(l2)));
        glm::vec3 l3 = glm::normalize(glm::vec3(std::sin(a), -std::abs(std::cos(a)) - 0.1f, 1e-4f));
        glm::vec3 l4 =
            glm::normalize(glm::vec3(std::sin(a), -std::abs(std::cos(a)) - 0.1f, -1e-4f));
        maxJump = std::max(maxJump, std::abs(sample(l3) - sample(l4)));
        maxErr = std::max(maxErr, std::abs(sample(up) - f(up)));
    }
    EXPECT_LT(maxJump, 2e-3f);
    EXPECT_LT(maxErr, 0.25f); // 6x6 texels of a linear function: small interpolation error
}
