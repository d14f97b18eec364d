// LDR-FLIP: zero for identical images, hand-computed values for uniform colour pairs (where
// the CSF and feature filters are the identity or zero), and properties of the full pipeline.
#include "core/Error.h"
#include "metrics/ImageMetrics.h"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace pb;
using pb::image::Image8;

namespace {

Image8 solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.pixels.resize(size_t(w) * h * 4);
    for (size_t i = 0; i < img.pixels.size(); i += 4) {
        img.pixels[i] = r;
        img.pixels[i + 1] = g;
        img.pixels[i + 2] = b;
        img.pixels[i + 3] = 255;
    }
    return img;
}

void setPixel(Image8& img, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

Image8 flipNoise(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    Image8 img = solid(w, h, 0, 0, 0);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (i % 4 != 3) img.pixels[i] = std::uint8_t(rng() & 0xff);
    return img;
}

// ---- the hand computation, written out from the textbook definitions (not the library) ----
// On a constant image every CSF filter (weights summing to 1) returns the input, and every
// feature detector (positive weights +1, negative -1) returns 0, so FLIP reduces to the colour
// error of the two colours: Hunt-adjusted CIELAB, HyAB, ^0.7 and the redistribution.
using Lab = std::array<double, 3>;

double decode(int v) { // sRGB transfer function
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Lab huntLabOfLinear(double r, double g, double b) {
    // sRGB -> XYZ (D65), 4-digit matrix; white = its row sums.
    const double X = 0.4124 * r + 0.3576 * g + 0.1805 * b;
    const double Y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    const double Z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
    auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116; };
    const double fx = f(X / 0.9505), fy = f(Y / 1.0), fz = f(Z / 1.089);
    const double L = 116 * fy - 16;
    // Hunt: chroma scaled by 0.01 L.
    return {L, 0.01 * L * 500 * (fx - fy), 0.01 * L * 200 * (fy - fz)};
}

Lab huntLabOfSrgb(int r, int g, int b) {
    return huntLabOfLinear(decode(r), decode(g), decode(b));
}

double hyab(const Lab& p, const Lab& q) {
    return std::abs(p[0] - q[0]) +
           std::sqrt((p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

double handFlip(const Lab& p, const Lab& q) {
    // cmax: HyAB of Hunt-adjusted pure green and pure blue, ^0.7 (about 203.3^0.7 = 41.2).
    const double cmax = std::pow(hyab(huntLabOfLinear(0, 1, 0), huntLabOfLinear(0, 0, 1)), 0.7);
    const double e = std::pow(hyab(p, q), 0.7);
    const double knee = 0.4 * cmax;
    return e < knee ? e * 0.95 / knee : 0.95 + (e - knee) / (cmax - knee) * 0.05;
}

} // namespace

TEST(Flip, IdenticalImagesHaveZeroError) {
    const Image8 a = flipNoise(19, 13, 5);
    const metrics::FlipResult r = metrics::ldrFlip(a, a);
    EXPECT_EQ(r.mean, 0.0);
    EXPECT_EQ(r.max, 0.0);
    ASSERT_EQ(r.map.channels, 1);
    ASSERT_EQ(r.map.width, 19);
    ASSERT_EQ(r.map.height, 13);
}

TEST(Flip, HandComputedGreyPair) {
    // Grey: a* = b* = 0, so HyAB = |L1 - L2|: L(128) = 53.59, L(100) = 42.37, dL = 11.22,
    // 11.22^0.7 = 5.43 < knee 0.4 * 41.2, so FLIP = 5.43 * 0.95 / 16.5 = 0.31.
    const double expected = handFlip(huntLabOfSrgb(128, 128, 128), huntLabOfSrgb(100, 100, 100));
    EXPECT_NEAR(expected, 0.31, 0.01) << "the derivation in the comment";
    const metrics::FlipResult r =
        metrics::ldrFlip(solid(24, 24, 100, 100, 100), solid(24, 24, 128, 128, 128));
    EXPECT_NEAR(r.mean, expected, 2e-3);
    EXPECT_NEAR(r.max, expected, 2e-3);
}

TEST(Flip, HandComputedColourPair) {
    // Exercises a*, b*, the Hunt scaling and the Euclidean part of HyAB.
    const double expected = handFlip(huntLabOfSrgb(200, 30, 30), huntLabOfSrgb(180, 60, 40));
    const metrics::FlipResult r =
        metrics::ldrFlip(solid(16, 16, 200, 30, 30), solid(16, 16, 180, 60, 40));
    EXPECT_NEAR(r.mean, expected, 2e-3);
    EXPECT_NEAR(r.max, expected, 2e-3);
}

TEST(Flip, BlackVersusWhiteIsNearOne) {
    // HyAB = 100 (L 0 vs 100), 100^0.7 = 25.1 > knee 16.5: 0.95 + (25.1 - 16.5) / (41.2 - 16.5)
    // * 0.05 = 0.967.
    const double expected = handFlip(huntLabOfSrgb(0, 0, 0), huntLabOfSrgb(255, 255, 255));
    EXPECT_NEAR(expected, 0.967, 2e-3) << "the derivation in the comment";
    const metrics::FlipResult r =
        metrics::ldrFlip(solid(40, 40, 0, 0, 0), solid(40, 40, 255, 255, 255));
    EXPECT_NEAR(r.mean, expected, 2e-3);
    EXPECT_GT(r.mean, 0.95);
}

TEST(Flip, FiltersLargerThanTheImageStillReduceToTheHandValue) {
    // 1x1: the 21-tap CSF and 19-tap detectors only ever see the repeated border pixel.
    const double expected = handFlip(huntLabOfSrgb(128, 128, 128), huntLabOfSrgb(100, 100, 100));
    EXPECT_NEAR(metrics::ldrFlip(solid(1, 1, 100, 100, 100), solid(1, 1, 128, 128, 128)).mean,
                expected, 2e-3);
}

TEST(Flip, GrowsWithTheSizeOfAColourDifference) {
    const Image8 ref = solid(20, 20, 128, 128, 128);
    double previous = 0;
    for (int delta : {2, 8, 32, 96}) {
        const double e =
            metrics::ldrFlip(solid(20, 20, std::uint8_t(128 + delta), 128, 128), ref).mean;
        EXPECT_GT(e, previous) << "delta " << delta;
        previous = e;
    }
}

TEST(Flip, IsSymmetricInItsArguments) {
    // Every step treats both images alike and compares them only through |t - r| (HyAB and the
    // feature differences), so swapping test and reference changes nothing.
    const Image8 a = flipNoise(24, 20, 6), b = flipNoise(24, 20, 7);
    const metrics::FlipResult ab = metrics::ldrFlip(a, b), ba = metrics::ldrFlip(b, a);
    EXPECT_DOUBLE_EQ(ab.mean, ba.mean);
    ASSERT_EQ(ab.map.pixels.size(), ba.map.pixels.size());
    for (size_t i = 0; i < ab.map.pixels.size(); ++i)
        EXPECT_EQ(ab.map.pixels[i], ba.map.pixels[i]);
    for (float v : ab.map.pixels) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }
}

TEST(Flip, ErrorStaysWhereTheDifferenceIs) {
    // A one-pixel dot: errors only within the filters' reach (CSF radius 10, detector radius 9
    // at 67 ppd), the largest at the dot.
    const Image8 ref = solid(41, 41, 128, 128, 128);
    Image8 test = ref;
    setPixel(test, 20, 20, 200, 200, 200);
    const metrics::FlipResult r = metrics::ldrFlip(test, ref);
    EXPECT_GT(r.max, 0.0);
    EXPECT_FLOAT_EQ(r.map.at(20, 20, 0), float(r.max));
    EXPECT_EQ(r.map.at(0, 0, 0), 0.0f);
    EXPECT_EQ(r.map.at(40, 40, 0), 0.0f);
    EXPECT_EQ(r.map.at(20, 0, 0), 0.0f);
}

TEST(Flip, FineDetailIsMoreVisibleAtFewerPixelsPerDegree) {
    // At lower ppd each pixel spans a larger visual angle, so the CSF blurs a one-pixel dot over
    // fewer pixels and it stands out more.
    const Image8 ref = solid(41, 41, 128, 128, 128);
    Image8 test = ref;
    setPixel(test, 20, 20, 200, 200, 200);
    EXPECT_GT(metrics::ldrFlip(test, ref, 20.0).max, metrics::ldrFlip(test, ref, 67.0).max);
}

TEST(Flip, RejectsBadArguments) {
    EXPECT_THROW(metrics::ldrFlip(solid(2, 2, 0, 0, 0), solid(3, 2, 0, 0, 0)), Error);
    EXPECT_THROW(metrics::ldrFlip(Image8{}, Image8{}), Error);
    EXPECT_THROW(metrics::ldrFlip(solid(2, 2, 0, 0, 0), solid(2, 2, 0, 0, 0), 0.0), Error);
    EXPECT_THROW(metrics::ldrFlip(solid(2, 2, 0, 0, 0), solid(2, 2, 0, 0, 0), std::nan("")), Error);
}
