// PSNR, SSIM, relative MSE and the heat-map ramp against values derived by hand on tiny images.
#include "metrics/ImageMetrics.h"
#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace pb;
using pb::image::Image8;
using pb::image::ImageF;

namespace {

Image8 imageMetricsSolid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                         std::uint8_t a = 255) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.pixels.resize(size_t(w) * h * 4);
    for (size_t i = 0; i < img.pixels.size(); i += 4) {
        img.pixels[i] = r;
        img.pixels[i + 1] = g;
        img.pixels[i + 2] = b;
        img.pixels[i + 3] = a;
    }
    return img;
}

void imageMetricsSetPixel(Image8& img, int x, int y, std::uint8_t r, std::uint8_t g,
                          std::uint8_t b) {
    std::uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

Image8 imageMetricsNoise(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    Image8 img = imageMetricsSolid(w, h, 0, 0, 0);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (i % 4 != 3) img.pixels[i] = std::uint8_t(rng() & 0xff);
    return img;
}

ImageF solidF(int w, int h, int channels, std::initializer_list<float> value) {
    ImageF img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    for (int i = 0; i < w * h; ++i)
        for (float v : value)
            img.pixels.push_back(v);
    return img;
}

double luma601(const std::uint8_t* p) {
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

} // namespace

// ---- PSNR ----

TEST(Psnr, IdenticalImagesAreInfinite) {
    const Image8 a = imageMetricsNoise(7, 5, 1);
    EXPECT_TRUE(std::isinf(metrics::psnr(a, a)));
    EXPECT_GT(metrics::psnr(a, a), 0);
}

TEST(Psnr, UniformOffsetHasKnownMse) {
    // Every R, G, B differs by 10: MSE = 100, PSNR = 10 log10(65025 / 100) = 28.13080 dB.
    // Alpha differs as well and must not count.
    const Image8 ref = imageMetricsSolid(4, 3, 100, 100, 100, 255),
                 test = imageMetricsSolid(4, 3, 110, 90, 110, 0);
    EXPECT_NEAR(metrics::psnr(test, ref), 28.13080, 1e-5);
}

TEST(Psnr, OneChannelOfOnePixelFullyWrong) {
    // 2x2 image, 12 colour values, one off by 255: MSE = 255^2 / 12, PSNR = 10 log10(12)
    // = 10.79181 dB.
    const Image8 ref = imageMetricsSolid(2, 2, 0, 0, 0);
    Image8 test = ref;
    imageMetricsSetPixel(test, 1, 1, 0, 255, 0);
    EXPECT_NEAR(metrics::psnr(test, ref), 10.79181, 1e-5);
}

TEST(Psnr, RejectsSizeMismatchAndEmpty) {
    EXPECT_THROW(metrics::psnr(imageMetricsSolid(2, 2, 0, 0, 0), imageMetricsSolid(2, 3, 0, 0, 0)),
                 Error);
    EXPECT_THROW(metrics::psnr(Image8{}, Image8{}), Error);
}

// ---- SSIM ----

TEST(Ssim, IdenticalImagesGiveOne) {
    const Image8 a = imageMetricsNoise(23, 17, 2);
    EXPECT_NEAR(metrics::ssim(a, a), 1.0, 1e-12);
}

TEST(Ssim, ConstantImagesReduceToTheLuminanceTerm) {
    // No variance, no covariance: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) with
    // C1 = (0.01 * 255)^2 = 6.5025. Grey 100 vs 150: 30006.5025 / 32506.5025 = 0.9230923105.
    // The same for 1x1 and for larger constant images.
    EXPECT_NEAR(metrics::ssim(imageMetricsSolid(1, 1, 100, 100, 100),
                              imageMetricsSolid(1, 1, 150, 150, 150)),
                0.9230923105, 1e-9);
    EXPECT_NEAR(metrics::ssim(imageMetricsSolid(13, 9, 100, 100, 100),
                              imageMetricsSolid(13, 9, 150, 150, 150)),
                0.9230923105, 1e-9);
}

TEST(Ssim, UsesRec601Luma) {
    // Pure red vs black: luma 0.299 * 255 = 76.245 vs 0, so SSIM = C1 / (76.245^2 + C1).
    const double expected = 6.5025 / (76.245 * 76.245 + 6.5025);
    EXPECT_NEAR(metrics::ssim(imageMetricsSolid(1, 1, 255, 0, 0), imageMetricsSolid(1, 1, 0, 0, 0)),
                expected, 1e-12);
    const std::uint8_t red[3] = {255, 0, 0};
    EXPECT_NEAR(luma601(red), 76.245, 1e-12);
}

TEST(Ssim, TwoPixelImageWithClippedWindow) {
    // x = (0, 255), y = (255, 0) in a 1x2 image. Each pixel's window holds both pixels with
    // Gaussian weights g(0) = 1 and g(1) = exp(-1 / (2 * 1.5^2)), renormalized to p (own
    // pixel) and q = 1 - p. At pixel 0: mx = 255 q, my = 255 p, var x = var y = p q 255^2,
    // cov = 0 - mx my = -p q 255^2; pixel 1 mirrors it. So
    // SSIM = (2 p q L + C1)(-2 p q L + C2) / (((p^2 + q^2) L + C1)(2 p q L + C2)), L = 255^2,
    // C2 = (0.03 * 255)^2 = 58.5225: -0.97226147.
    Image8 x = imageMetricsSolid(2, 1, 0, 0, 0), y = imageMetricsSolid(2, 1, 0, 0, 0);
    imageMetricsSetPixel(x, 1, 0, 255, 255, 255);
    imageMetricsSetPixel(y, 0, 0, 255, 255, 255);
    EXPECT_NEAR(metrics::ssim(x, y), -0.97226147, 1e-7);
}

TEST(Ssim, MoreNoiseScoresLower) {
    const Image8 ref = imageMetricsNoise(32, 32, 3);
    std::mt19937 rng(4);
    double previous = 1.0;
    for (int amplitude : {4, 16, 64}) {
        Image8 test = ref;
        for (size_t i = 0; i < test.pixels.size(); ++i) {
            if (i % 4 == 3) continue;
            const int v = int(test.pixels[i]) + int(rng() % (2 * amplitude + 1)) - amplitude;
            test.pixels[i] = std::uint8_t(std::clamp(v, 0, 255));
        }
        const double s = metrics::ssim(test, ref);
        EXPECT_LT(s, previous) << "amplitude " << amplitude;
        previous = s;
    }
}

TEST(Ssim, RejectsSizeMismatch) {
    EXPECT_THROW(metrics::ssim(imageMetricsSolid(3, 2, 0, 0, 0), imageMetricsSolid(2, 3, 0, 0, 0)),
                 Error);
}

// ---- relative MSE ----

TEST(RelativeMse, UniformTenPercentErrorGivesOnePercent) {
    // (2.2 - 2)^2 / 2^2 = 0.01 per value; the 4th channel (weight) is not radiance.
    const ImageF ref = solidF(3, 2, 4, {2, 2, 2, 1}), test = solidF(3, 2, 4, {2.2f, 1.8f, 2.2f, 0});
    EXPECT_NEAR(metrics::relativeMse(test, ref), 0.01, 1e-6);
}

TEST(RelativeMse, ZeroReferenceCases) {
    const ImageF zero = solidF(2, 2, 3, {0, 0, 0}), one = solidF(2, 2, 3, {1, 0, 0});
    EXPECT_EQ(metrics::relativeMse(zero, zero), 0.0);
    EXPECT_TRUE(std::isinf(metrics::relativeMse(one, zero)));
    EXPECT_EQ(metrics::relativeMse(one, one), 0.0);
}

TEST(RelativeMse, RejectsMismatches) {
    EXPECT_THROW(metrics::relativeMse(solidF(2, 2, 3, {0, 0, 0}), solidF(2, 2, 4, {0, 0, 0, 0})),
                 Error);
    EXPECT_THROW(metrics::relativeMse(solidF(2, 2, 3, {0, 0, 0}), solidF(2, 1, 3, {0, 0, 0})),
                 Error);
}

// ---- heat map ----

TEST(ErrorHeatMap, ZeroIsBlackAndLumaRisesWithError) {
    ImageF map;
    map.width = 65;
    map.height = 1;
    map.channels = 1;
    for (int i = 0; i < 65; ++i)
        map.pixels.push_back(float(i) / 64);
    const Image8 img = metrics::errorHeatMap(map);
    ASSERT_EQ(img.width, 65);
    EXPECT_EQ(img.pixels[0], 0);
    EXPECT_EQ(img.pixels[1], 0);
    EXPECT_EQ(img.pixels[2], 0);
    EXPECT_EQ(img.pixels[3], 255);
    double previous = -1;
    for (int i = 0; i < 65; ++i) {
        const double l = luma601(&img.pixels[size_t(i) * 4]);
        EXPECT_GT(l, previous) << "step " << i;
        previous = l;
    }
    EXPECT_GT(previous, 200) << "the top of the ramp should be bright";
}

TEST(ErrorHeatMap, ClampsAboveMaxAndShowsNanAsWorst) {
    ImageF map;
    map.width = 4;
    map.height = 1;
    map.channels = 1;
    map.pixels = {0.5f, 7.0f, std::nanf(""), 0.25f};
    const Image8 img = metrics::errorHeatMap(map, 0.5f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(img.pixels[size_t(4 + c)], img.pixels[size_t(c)]) << "above max";
        EXPECT_EQ(img.pixels[size_t(8 + c)], img.pixels[size_t(c)]) << "NaN";
    }
    EXPECT_LT(luma601(&img.pixels[12]), luma601(&img.pixels[0]));
    EXPECT_THROW(metrics::errorHeatMap(map, 0.0f), Error);
    EXPECT_THROW(metrics::errorHeatMap(ImageF{}), Error);
}
