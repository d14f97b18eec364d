// Mean SSIM of the luma, Wang, Bovik, Sheikh, Simoncelli: "Image quality assessment: from error
// visibility to structural similarity", IEEE TIP 13(4), 2004, Eq. 13 with the paper's
// 11x11 circular-symmetric Gaussian window (sigma 1.5) and K1 = 0.01, K2 = 0.03, L = 255.
// Differences from the authors' MATLAB code (their choices are for large photographs):
//  - the window is clipped to the image at the border and renormalized instead of keeping only
//    windows that fit ('valid'), so tiny images have an SSIM and every pixel counts;
//  - no automatic downsampling of large images.
#include "metrics/ImageChecks.h"
#include "metrics/ImageMetrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace pb::metrics {
namespace {

constexpr int kRadius = 5; // 11x11 window
constexpr double kSigma = 1.5;

using SsimPlane = std::vector<double>;

SsimPlane luma(const image::Image8& img) {
    SsimPlane out(size_t(img.width) * img.height);
    for (size_t i = 0; i < out.size(); ++i) {
        const auto* p = &img.pixels[i * 4];
        out[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    }
    return out;
}

// Weighted mean over the clipped window. The Gaussian is separable and so is its clipped,
// renormalized version (the normalizer is the product of the in-image 1D sums), so two 1D
// passes give exactly the 2D result.
SsimPlane windowMean(const SsimPlane& in, int w, int h) {
    std::array<double, 2 * kRadius + 1> g{};
    for (int i = -kRadius; i <= kRadius; ++i)
        g[i + kRadius] = std::exp(-double(i * i) / (2 * kSigma * kSigma));
    auto pass = [&](const SsimPlane& src, bool horizontal) {
        SsimPlane dst(src.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0, weight = 0;
                for (int i = -kRadius; i <= kRadius; ++i) {
                    const int sx = horizontal ? x + i : x, sy = horizontal ? y : y + i;
                    if (sx < 0 || sx >= w || sy < 0 || sy >= h) continue;
                    sum += g[i + kRadius] * src[size_t(sy) * w + sx];
                    weight += g[i + kRadius];
                }
                dst[size_t(y) * w + x] = sum / weight;
            }
        return dst;
    };
    return pass(pass(in, true), false);
}

} // namespace

double ssim(const image::Image8& test, const image::Image8& reference) {
    requireComparable("ssim", test, reference);
    const int w = test.width, h = test.height;
    const SsimPlane x = luma(test), y = luma(reference);
    SsimPlane xx(x.size()), yy(x.size()), xy(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const SsimPlane mx = windowMean(x, w, h), my = windowMean(y, w, h);
    const SsimPlane exx = windowMean(xx, w, h), eyy = windowMean(yy, w, h),
                    exy = windowMean(xy, w, h);
    const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    double sum = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        // Biased (weighted) moments, as the reference implementation's filtering gives them;
        // rounding can push a zero variance slightly negative, which would not be a variance.
        const double vx = std::max(0.0, exx[i] - mx[i] * mx[i]);
        const double vy = std::max(0.0, eyy[i] - my[i] * my[i]);
        const double cov = exy[i] - mx[i] * my[i];
        sum += ((2 * mx[i] * my[i] + c1) * (2 * cov + c2)) /
               ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    }
    return sum / double(x.size());
}

} // namespace pb::metrics
