// The truth's camera-hit albedo goes through the GBuffer's SRGB8_A8 storage
// (truth/GBufferAlbedo.h): the sRGB transfer function, rounding to the nearest of 256 codes,
// and back.
#include "truth/GBufferAlbedo.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb;

namespace {

double gbufferAlbedoEncode(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double gbufferAlbedoDecode(double s) {
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

} // namespace

TEST(GBufferAlbedo, EveryCodeIsStoredAsItself) {
    for (int k = 0; k <= 255; ++k) {
        const float v = float(gbufferAlbedoDecode(k / 255.0));
        EXPECT_NEAR(truth::throughSrgb8(v), v, 1e-6f * std::max(v, 1e-3f)) << "code " << k;
    }
}

TEST(GBufferAlbedo, RoundsToTheNearestCodeAndClampsToTheUnitRange) {
    float previous = 0.0f;
    for (int i = 0; i <= 10000; ++i) {
        const float v = float(i) / 10000.0f;
        const float stored = truth::throughSrgb8(v);
        // The stored value is a code, within half a code of v's encoding.
        const double code = gbufferAlbedoEncode(stored) * 255.0;
        EXPECT_NEAR(code, std::round(code), 2e-3) << v;
        EXPECT_LE(std::abs(code - gbufferAlbedoEncode(v) * 255.0), 0.5 + 2e-3) << v;
        EXPECT_GE(stored, previous) << v; // monotonic
        previous = stored;
    }
    EXPECT_EQ(truth::throughSrgb8(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(truth::throughSrgb8(1.0f), 1.0f);
    EXPECT_EQ(truth::throughSrgb8(-0.5f), 0.0f);
    EXPECT_FLOAT_EQ(truth::throughSrgb8(1.5f), 1.0f);
    // 0.5 encodes to 187.5: stored as code 188, 0.58% brighter.
    EXPECT_NEAR(truth::throughSrgb8(0.5f), gbufferAlbedoDecode(188.0 / 255.0), 1e-6);
    const glm::vec3 c = truth::asGBufferStoresAlbedo({0.5f, 0.0f, 1.0f});
    EXPECT_NEAR(c.x, gbufferAlbedoDecode(188.0 / 255.0), 1e-6);
    EXPECT_EQ(c.y, 0.0f);
    EXPECT_FLOAT_EQ(c.z, 1.0f);
}
