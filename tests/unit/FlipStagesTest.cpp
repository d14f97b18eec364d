// LDR-FLIP's filtering stages against direct, non-separable evaluations of the paper's kernel
// definitions, a hand value for the feature error at a step edge, and the final combination.
#include "metrics/FlipStages.h"
#include "metrics/ColourSpaces.h"
#include "metrics/ImageMetrics.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace pb;
using pb::image::Image8;
using pb::metrics::Plane;

namespace {

constexpr double kPi = std::numbers::pi;

Image8 noise(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    Image8 img;
    img.width = w;
    img.height = h;
    img.pixels.resize(size_t(w) * h * 4, 255);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (i % 4 != 3) img.pixels[i] = std::uint8_t(rng() & 0xff);
    return img;
}

// Direct 2D convolution with clamp-to-edge borders; kernel(dx, dy) is normalized here the way
// the caller says.
Plane convolve2d(const Plane& in, int radius, const std::vector<double>& kernel) {
    Plane out{in.width, in.height, std::vector<double>(in.v.size())};
    const int n = 2 * radius + 1;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            double s = 0;
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int sx = std::clamp(x + dx, 0, in.width - 1);
                    const int sy = std::clamp(y + dy, 0, in.height - 1);
                    s += kernel[size_t((dy + radius) * n + dx + radius)] * in.at(sx, sy);
                }
            out.at(x, y) = s;
        }
    return out;
}

} // namespace

TEST(FlipStages, CsfFiltersEqualThePapersTwoDimensionalKernels) {
    // s(r) = a1 sqrt(pi/b1) exp(-pi^2 r^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2 / b2), r in
    // degrees, normalized to sum 1; radius ceil(3 sqrt(0.04 / (2 pi^2)) ppd) = 5 at 30 ppd.
    const double ppd = 30;
    const int radius = int(std::ceil(3 * std::sqrt(0.04 / (2 * kPi * kPi)) * ppd));
    ASSERT_EQ(radius, 5);
    const double params[3][4] = {
        {1, 0.0047, 0, 1e-5}, {1, 0.0053, 0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
    const Image8 img = noise(13, 11, 21);
    const auto filtered = metrics::flip::csfFilteredOpponent(img, ppd);
    for (int c = 0; c < 3; ++c) {
        Plane in{img.width, img.height, {}};
        for (size_t i = 0; i < size_t(img.width) * img.height; ++i) {
            const metrics::colour::Vec3 rgb{
                metrics::colour::srgbToLinear(img.pixels[i * 4] / 255.0),
                metrics::colour::srgbToLinear(img.pixels[i * 4 + 1] / 255.0),
                metrics::colour::srgbToLinear(img.pixels[i * 4 + 2] / 255.0)};
            in.v.push_back(
                metrics::colour::xyzToYcxcz(metrics::colour::linearRgbToXyz(rgb))[size_t(c)]);
        }
        std::vector<double> k;
        double sum = 0;
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                const double r2 = (dx * dx + dy * dy) / (ppd * ppd);
                const auto [a1, b1, a2, b2] = params[c];
                k.push_back(a1 * std::sqrt(kPi / b1) * std::exp(-kPi * kPi * r2 / b1) +
                            a2 * std::sqrt(kPi / b2) * std::exp(-kPi * kPi * r2 / b2));
                sum += k.back();
            }
        for (double& v : k)
            v /= sum;
        const Plane expected = convolve2d(in, radius, k);
        for (size_t i = 0; i < expected.v.size(); ++i)
            ASSERT_NEAR(filtered[size_t(c)].v[i], expected.v[i], 1e-9)
                << "channel " << c << " pixel " << i;
    }
}

TEST(FlipStages, DetectorsEqualThePapersTwoDimensionalKernels) {
    // sigma = 0.5 * 0.082 * ppd, radius ceil(3 sigma); edge: -x G, point: (x^2/sigma^2 - 1) G,
    // positive weights scaled to sum 1, negative to -1; magnitude of the x and y responses.
    const double ppd = 40, sigma = 0.5 * 0.082 * ppd;
    const int radius = int(std::ceil(3 * sigma));
    const int n = 2 * radius + 1;
    auto kernel = [&](bool point, bool alongX) {
        std::vector<double> k;
        double pos = 0, neg = 0;
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                const double g = std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
                const double t = alongX ? dx : dy;
                k.push_back(point ? (t * t / (sigma * sigma) - 1) * g : -t * g);
                (k.back() > 0 ? pos : neg) += std::abs(k.back());
            }
        for (double& v : k)
            v /= v > 0 ? pos : neg;
        return k;
    };
    std::mt19937 rng(22);
    Plane lum{17, 12, {}};
    for (int i = 0; i < 17 * 12; ++i)
        lum.v.push_back((rng() % 1000) / 999.0);
    const auto response = metrics::flip::featureResponse(lum, ppd);
    for (bool point : {false, true}) {
        const Plane gx = convolve2d(lum, radius, kernel(point, true));
        const Plane gy = convolve2d(lum, radius, kernel(point, false));
        const Plane& got = point ? response.points : response.edges;
        for (size_t i = 0; i < gx.v.size(); ++i)
            ASSERT_NEAR(got.v[i], std::hypot(gx.v[i], gy.v[i]), 1e-12)
                << (point ? "point " : "edge ") << i;
    }
    EXPECT_EQ(size_t(n * n), kernel(false, true).size());
}

TEST(FlipStages, FeatureErrorAtAStepEdgeByHand) {
    // Reference: black | white (luminance 0 | 1); test: all black. Next to the step the edge
    // detector sums all its negative (or positive) weights over the white side: |response| = 1.
    // The point detector there sums at most half of its positive weights and some negative
    // ones: |response| <= 0.5. Feature error = (max(1, <=0.5) / sqrt 2)^0.5 = 0.8408964.
    // Beyond the detector radius (9 at 67 ppd) there is no feature at all.
    Image8 ref, test;
    ref.width = test.width = 30;
    ref.height = test.height = 6;
    ref.pixels.assign(30 * 6 * 4, 255);
    test.pixels.assign(30 * 6 * 4, 0);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 15; ++x)
            for (int c = 0; c < 3; ++c)
                ref.pixels[(size_t(y) * 30 + x) * 4 + c] = 0;
    const auto edges = metrics::flip::featureResponse(metrics::flip::luminance(ref), 67.0);
    const Plane fe = metrics::flip::featureError(test, ref, 67.0);
    for (int y = 0; y < 6; ++y) {
        for (int x : {14, 15}) {
            EXPECT_NEAR(edges.edges.at(x, y), 1.0, 1e-12);
            EXPECT_LE(edges.points.at(x, y), 0.5);
            EXPECT_NEAR(fe.at(x, y), 0.8408964, 1e-7);
        }
        // Zero up to rounding: the detector weights sum to 0 within 1e-16, and the square root
        // of qf = 0.5 turns that into ~1e-8.
        EXPECT_NEAR(fe.at(0, y), 0.0, 1e-7);
        EXPECT_NEAR(fe.at(29, y), 0.0, 1e-7);
    }
}

TEST(FlipStages, FlipIsColourErrorToThePowerOfOneMinusFeatureError) {
    const Image8 a = noise(20, 16, 23), b = noise(20, 16, 24);
    const Plane colour = metrics::flip::colourError(a, b, 67.0);
    const Plane feature = metrics::flip::featureError(a, b, 67.0);
    const metrics::FlipResult r = metrics::ldrFlip(a, b, 67.0);
    double sum = 0;
    for (size_t i = 0; i < colour.v.size(); ++i) {
        const double expected = std::min(1.0, std::pow(colour.v[i], 1 - feature.v[i]));
        EXPECT_NEAR(r.map.pixels[i], expected, 1e-6);
        sum += expected;
    }
    EXPECT_NEAR(r.mean, sum / double(colour.v.size()), 1e-12);
}
