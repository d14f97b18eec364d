// BC6H encoder: round trips through the (spec-checked, see Bc6hDecodeTest.cpp) decoder.
//
// Error bounds and where they come from. The encoder works in half-float bit space, where one
// step ("unit") is one half ulp: a relative step of 2^-11..2^-10 for normal values. A block
// whose values lie on a line there is limited by the 16 (one region) or 8 (two regions)
// palette entries: with entries evenly spread over a range of R units the worst texel is
// R/30 units off (half a step), plus endpoint quantisation and the final rounding.
#include "probes/bc6h/Bc6h.h"
#include "probes/bc6h/Bc6hFit.h"

#include "core/Error.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace pb::probes;

std::vector<float> roundTrip(const std::vector<float>& src, int w, int h, int stride = 3,
                             Bc6hQuality q = Bc6hQuality::Normal) {
    const std::vector<std::uint8_t> blocks = encodeBc6hUf16(src.data(), w, h, stride, q);
    EXPECT_EQ(blocks.size(), bc6hSizeBytes(w, h));
    return decodeBc6hUf16(blocks.data(), w, h);
}

// The two half floats that bracket v (equal when v is a half).
std::pair<float, float> bracketingHalves(float v) {
    int lo = 0, hi = 0x7BFF;
    while (lo < hi) { // largest bit pattern whose value <= v
        const int mid = (lo + hi + 1) / 2;
        if (glm::unpackHalf1x16(static_cast<glm::uint16>(mid)) <= v)
            lo = mid;
        else
            hi = mid - 1;
    }
    const float below = glm::unpackHalf1x16(static_cast<glm::uint16>(lo));
    if (below == v || lo == 0x7BFF) return {below, below};
    return {below, glm::unpackHalf1x16(static_cast<glm::uint16>(lo + 1))};
}

std::vector<float> constantImage(int w, int h, float r, float g, float b) {
    std::vector<float> img(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < img.size(); i += 3) {
        img[i] = r;
        img[i + 1] = g;
        img[i + 2] = b;
    }
    return img;
}

// Mode 14 stores a 16-bit base: any constant block is representable to half precision.
TEST(Bc6hEncode, ConstantBlocksDecodeToABracketingHalf) {
    const float values[] = {0.0f,     1e-7f,  6.1e-5f, 1e-3f,    0.1f,     0.5f,    1.0f,
                            3.14159f, 100.0f, 1000.5f, 12345.0f, 65000.0f, 65504.0f};
    for (float v : values) {
        const float rgb[3] = {v, std::min(v * 0.37f, 65504.0f), std::min(v * 1.9f, 65504.0f)};
        const std::vector<float> out = roundTrip(constantImage(4, 4, rgb[0], rgb[1], rgb[2]), 4, 4);
        for (int t = 0; t < 16; ++t) {
            for (int c = 0; c < 3; ++c) {
                const auto [below, above] = bracketingHalves(rgb[c]);
                const float d = out[t * 3 + c];
                EXPECT_TRUE(d == below || d == above) << "value " << rgb[c] << " decoded " << d
                                                      << " (" << below << ", " << above << ")";
            }
        }
    }
}

TEST(Bc6hEncode, ExactHalvesInAConstantBlockAreExact) {
    for (glm::uint16 bits : {0x0001, 0x03FF, 0x0400, 0x3C00, 0x3555, 0x5A5A, 0x7BFF}) {
        const float v = glm::unpackHalf1x16(bits);
        const std::vector<float> out = roundTrip(constantImage(8, 4, v, v, v), 8, 4);
        for (float d : out)
            EXPECT_EQ(d, v) << "half 0x" << std::hex << bits;
    }
}

TEST(Bc6hEncode, ZerosAndMaximumAreExact) {
    for (Bc6hQuality q : {Bc6hQuality::Fast, Bc6hQuality::Normal, Bc6hQuality::High}) {
        for (float d : roundTrip(constantImage(8, 8, 0, 0, 0), 8, 8, 3, q))
            EXPECT_EQ(d, 0.0f);
        for (float d : roundTrip(constantImage(8, 8, 65504, 65504, 65504), 8, 8, 3, q))
            EXPECT_EQ(d, 65504.0f);
    }
}

// Negative and NaN become 0, anything above the half maximum 65504. A block holding only 0
// and 65504 is exact: they are the two ends of the palette.
TEST(Bc6hEncode, ClampsNegativeNanAndHugeValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float low[] = {nan, -1.0f, -inf, -0.0f, 0.0f, -1e-30f, -65504.0f, -nan};
    const float high[] = {inf, 1e30f, 70000.0f, 65504.0f, 65520.0f, 3e38f, 1e5f, inf};
    std::vector<float> img(16 * 3);
    for (int t = 0; t < 16; ++t)
        for (int c = 0; c < 3; ++c)
            img[t * 3 + c] = ((t + c) % 2 == 0) ? low[t % 8] : high[t % 8];
    const std::vector<float> out = roundTrip(img, 4, 4);
    for (int i = 0; i < 48; ++i) {
        const int t = i / 3, c = i % 3;
        EXPECT_EQ(out[i], ((t + c) % 2 == 0) ? 0.0f : 65504.0f) << "texel " << t << " ch " << c;
    }
    // The report measures against the clamped source, so this round trip has no error.
    const Bc6hErrorStats s = bc6hRoundTripError(img.data(), 4, 4, 3);
    EXPECT_EQ(s.maxAbs, 0.0);
    EXPECT_EQ(s.channels, 48u);
}

TEST(Bc6hEncode, RejectsBadArguments) {
    const std::vector<float> img(8 * 8 * 4, 1.0f);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 6, 4, 3), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 4, 6, 3), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 0, 4, 3), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 4, -4, 3), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 4, 4, 1), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(img.data(), 4, 4, 5), pb::Error);
    EXPECT_THROW(encodeBc6hUf16(nullptr, 4, 4, 3), pb::Error);
    EXPECT_THROW(bc6hSizeBytes(3, 4), pb::Error);
    EXPECT_EQ(bc6hSizeBytes(8, 12), 6u * 16u);
}

TEST(Bc6hEncode, StrideFourIgnoresAlphaAndStrideTwoEncodesZeroBlue) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    std::vector<float> rgba(16 * 8 * 4), rgb(16 * 8 * 3), rg(16 * 8 * 2), rg0(16 * 8 * 3);
    for (int t = 0; t < 16 * 8; ++t) {
        for (int c = 0; c < 4; ++c)
            rgba[t * 4 + c] = u(rng);
        for (int c = 0; c < 3; ++c)
            rgb[t * 3 + c] = rgba[t * 4 + c];
        rg[t * 2] = rg0[t * 3] = rgba[t * 4];
        rg[t * 2 + 1] = rg0[t * 3 + 1] = rgba[t * 4 + 1];
    }
    EXPECT_EQ(encodeBc6hUf16(rgba.data(), 16, 8, 4), encodeBc6hUf16(rgb.data(), 16, 8, 3));
    EXPECT_EQ(encodeBc6hUf16(rg.data(), 16, 8, 2), encodeBc6hUf16(rg0.data(), 16, 8, 3));
    const std::vector<float> out = roundTrip(rg, 16, 8, 2);
    for (int t = 0; t < 16 * 8; ++t)
        EXPECT_EQ(out[t * 3 + 2], 0.0f);
}

std::vector<float> hdrBlocks(int w, int h, unsigned seed) {
    // Each 4x4 block: a level log-uniform in 1e-3..1e4, one tint (0.25..1 per channel) and
    // +-20% texel-to-texel brightness: locally smooth, globally 7 decades, like lit probes.
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> img(static_cast<std::size_t>(w) * h * 3);
    for (int by = 0; by < h / 4; ++by) {
        for (int bx = 0; bx < w / 4; ++bx) {
            const float level = std::pow(10.0f, -3.0f + 7.0f * u(rng));
            float tint[3];
            for (float& t : tint)
                t = 0.25f + 0.75f * u(rng);
            for (int y = 0; y < 4; ++y) {
                for (int x = 0; x < 4; ++x) {
                    const float v = level * (0.8f + 0.4f * u(rng));
                    for (int c = 0; c < 3; ++c)
                        img[((by * 4 + y) * w + bx * 4 + x) * 3 + c] = v * tint[c];
                }
            }
        }
    }
    return img;
}

// A tinted block is a line along (1,1,1) in half-bit space (log2 of a product is a sum), so
// only the palette spacing limits it: brightness 0.8..1.2 spans log2(1.5) * 1024 = 599 units,
// 15 steps of ~40, so the worst texel is ~20 units off, plus <= 8 for 11/12-bit endpoints and
// 1 for rounding: ~29 units, 2.9% at the bottom of a binade. Mean is about a quarter step.
TEST(Bc6hEncode, RandomHdrBlocksSpanningSevenDecades) {
    const int w = 64, h = 64;
    const std::vector<float> src = hdrBlocks(w, h, 1234);
    for (Bc6hQuality q : {Bc6hQuality::Fast, Bc6hQuality::Normal, Bc6hQuality::High}) {
        const std::vector<float> out = roundTrip(src, w, h, 3, q);
        const Bc6hErrorStats s = measureBc6hError(src.data(), 3, out.data(), w, h, 1e-9);
        SCOPED_TRACE("quality " + std::to_string(static_cast<int>(q)));
        EXPECT_LT(s.maxRel, 0.065);
        EXPECT_LT(s.meanRel, 0.009);
        RecordProperty("maxRel_q" + std::to_string(static_cast<int>(q)), std::to_string(s.maxRel));
        RecordProperty("meanRel_q" + std::to_string(static_cast<int>(q)),
                       std::to_string(s.meanRel));
    }
}

std::vector<float> gradient(int w, int h, bool blueAlongY) {
    // R linear 0.05..1.05, G logarithmic 1e-3..1e4 (a factor 1.5 every 4 texels), B 2..0.5,
    // all along x; or B along y, which makes each block a plane rather than a curve.
    std::vector<float> img(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* p = &img[(static_cast<std::size_t>(y) * w + x) * 3];
            p[0] = 0.05f + x / static_cast<float>(w);
            p[1] = std::pow(10.0f, -3.0f + 7.0f * x / (w - 1.0f));
            p[2] =
                2.0f - 1.5f * (blueAlongY ? y / static_cast<float>(h) : x / static_cast<float>(w));
        }
    }
    return img;
}

// One-directional ramps: every block is a short curve in half-bit space, nearly a line.
// The log ramp spans ~600 units per block (40 per index step, so <= 20 off), the linear ramps
// much less; the binade kinks (see RandomHdrBlocks) add a few tens of units.
TEST(Bc6hEncode, Gradients) {
    const int w = 128, h = 16;
    const std::vector<float> src = gradient(w, h, false);
    const std::vector<float> out = roundTrip(src, w, h);
    const Bc6hErrorStats s = measureBc6hError(src.data(), 3, out.data(), w, h, 1e-9);
    EXPECT_LT(s.maxRel, 0.035);
    EXPECT_LT(s.meanRel, 0.005);
}

// Blue changing along y while red and green change along x: each block is a plane, which one
// line per region cannot follow; the error is set by the smaller, perpendicular extent.
TEST(Bc6hEncode, TwoDirectionalGradients) {
    const int w = 128, h = 32;
    const std::vector<float> src = gradient(w, h, true);
    const std::vector<float> out = roundTrip(src, w, h);
    const Bc6hErrorStats s = measureBc6hError(src.data(), 3, out.data(), w, h, 1e-9);
    EXPECT_LT(s.maxRel, 0.09);
    EXPECT_LT(s.meanRel, 0.02);
}

// Independent noise in every channel of every texel over 7 decades: no 4x4 block of one or
// two lines can follow 48 unrelated values, so there is no per-texel bound. What must hold:
// valid output, and far less error than the data's own spread (a regression guard).
TEST(Bc6hEncode, WhiteNoiseHdrStaysValid) {
    const int w = 32, h = 32;
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> src(static_cast<std::size_t>(w) * h * 3);
    for (float& v : src)
        v = std::pow(10.0f, -3.0f + 7.0f * u(rng));
    const std::vector<float> out = roundTrip(src, w, h);
    double sumLog = 0.0;
    for (std::size_t i = 0; i < src.size(); ++i) {
        ASSERT_TRUE(std::isfinite(out[i]));
        ASSERT_GE(out[i], 0.0f);
        ASSERT_LE(out[i], 65504.0f);
        sumLog += std::fabs(std::log2(std::max(out[i], 1e-6f) / src[i]));
    }
    EXPECT_LT(sumLog / src.size(), 3.0); // mean |log2 error| in stops; data spread is ~23
}

TEST(Bc6hEncode, Deterministic) {
    const std::vector<float> src = hdrBlocks(32, 32, 5);
    for (Bc6hQuality q : {Bc6hQuality::Fast, Bc6hQuality::Normal, Bc6hQuality::High})
        EXPECT_EQ(encodeBc6hUf16(src.data(), 32, 32, 3, q),
                  encodeBc6hUf16(src.data(), 32, 32, 3, q));
}

// Higher quality searches a superset of the candidates of lower quality, so per block the
// encoder's own error (squared half-bit distance) can only go down.
TEST(Bc6hEncode, HigherQualityNeverIncreasesBlockError) {
    const int w = 32, h = 32;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> src = hdrBlocks(w, h, 11);
    for (std::size_t i = 0; i < src.size() / 2; ++i)
        src[i] = std::pow(10.0f, 2.0f * u(rng));
    auto blockErrors = [&](Bc6hQuality q) {
        const std::vector<float> out = roundTrip(src, w, h, 3, q);
        std::vector<double> err((w / 4) * (h / 4), 0.0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 3 + c;
                    const double d =
                        bc6h::halfBitsContinuous(out[i]) - bc6h::halfBitsContinuous(src[i]);
                    err[(y / 4) * (w / 4) + x / 4] += d * d;
                }
        return err;
    };
    const std::vector<double> fast = blockErrors(Bc6hQuality::Fast);
    const std::vector<double> normal = blockErrors(Bc6hQuality::Normal);
    const std::vector<double> high = blockErrors(Bc6hQuality::High);
    for (std::size_t b = 0; b < fast.size(); ++b) {
        EXPECT_LE(normal[b], fast[b] * 1.0001 + 1e-3) << "block " << b;
        EXPECT_LE(high[b], normal[b] * 1.0001 + 1e-3) << "block " << b;
    }
}

// The encoder's packing against the decoder for all 14 modes, including those the encoder
// rarely picks: random endpoints within each mode's delta range (wrapping included), random
// indices with clear anchor bits, packed, decoded and compared with the values computed from
// the endpoints directly. (Decoder vs specification: Bc6hDecodeTest.cpp and the GL test.)
TEST(Bc6hEncode, PackedBlocksOfEveryModeDecodeToTheirEndpoints) {
    using namespace bc6h;
    std::mt19937 rng(77);
    for (int mode = 0; mode < kModeCount; ++mode) {
        const ModeInfo& info = modeInfo(mode);
        for (int trial = 0; trial < 50; ++trial) {
            Encoding enc;
            enc.mode = mode;
            enc.partition = info.regions == 2 ? static_cast<int>(rng() % 32) : 0;
            const int mask = (1 << info.epb) - 1;
            for (int c = 0; c < 3; ++c) {
                enc.ep[0][c] = static_cast<int>(rng()) & mask;
                for (int e = 1; e < 2 * info.regions; ++e) {
                    if (!info.transformed) {
                        enc.ep[e][c] = static_cast<int>(rng()) & mask;
                        continue;
                    }
                    const int range = 1 << info.delta[c];
                    const int delta = static_cast<int>(rng() % range) - range / 2;
                    enc.ep[e][c] = (enc.ep[0][c] + delta) & mask;
                }
            }
            const int count = info.regions == 2 ? 8 : 16;
            for (int t = 0; t < 16; ++t)
                enc.index[t] = static_cast<std::uint8_t>(rng() % count);
            enc.index[0] %= count / 2;
            if (info.regions == 2) enc.index[kAnchor2[enc.partition]] %= count / 2;

            std::uint8_t block[16];
            pack(enc, block);
            float out[48];
            decodeBc6hUf16Block(block, out);
            const int* weights = info.regions == 2 ? kWeights3 : kWeights4;
            for (int t = 0; t < 16; ++t) {
                const int s = info.regions == 2 ? (kPartitions[enc.partition] >> t) & 1 : 0;
                for (int c = 0; c < 3; ++c) {
                    const int i = interpolate(unquantize(enc.ep[2 * s][c], info.epb),
                                              unquantize(enc.ep[2 * s + 1][c], info.epb),
                                              weights[enc.index[t]]);
                    const float want =
                        glm::unpackHalf1x16(static_cast<glm::uint16>(finishUnsigned(i)));
                    ASSERT_EQ(out[t * 3 + c], want)
                        << "mode " << mode + 1 << " trial " << trial << " texel " << t;
                }
            }
        }
    }
}

TEST(Bc6hErrorReport, MeasuresAbsoluteAndRelativeError) {
    // Stride 4 (the 4th float is ignored): texels (1, 2, 0) and (-1 -> 0, 0.5, 8).
    const float src[] = {1.0f, 2.0f, 0.0f, 4.0f, -1.0f, 0.5f, 8.0f, 1.0f};
    const float dec[] = {1.5f, 2.0f, 9.0f, 3.0f, 0.25f, 0.5f};
    // |error|: 0.5, 0, 9, 3, 0.25, 7.5; relative to max(source, 0.01): 0.5, 0, 900, 300, 0.5,
    // 0.9375.
    const Bc6hErrorStats s = measureBc6hError(src, 4, dec, 2, 1, 0.01);
    EXPECT_EQ(s.channels, 6u);
    EXPECT_DOUBLE_EQ(s.maxAbs, 9.0);
    EXPECT_DOUBLE_EQ(s.meanAbs, 20.25 / 6.0);
    EXPECT_DOUBLE_EQ(s.maxRel, 900.0);
    EXPECT_DOUBLE_EQ(s.meanRel, (0.5 + 900.0 + 300.0 + 0.5 + 0.9375) / 6.0);
    EXPECT_NEAR(s.rmse, std::sqrt((0.25 + 81.0 + 9.0 + 0.0625 + 56.25) / 6.0), 1e-12);
    EXPECT_THROW(measureBc6hError(src, 5, dec, 2, 1), pb::Error);
}

} // namespace
