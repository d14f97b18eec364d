// LDR-FLIP feature pipeline (steps 7-8 of the list in Flip.cpp).
#include "metrics/ColourSpaces.h"
#include "metrics/FlipStages.h"

#include <algorithm>
#include <cmath>

namespace pb::metrics::flip {
namespace {

constexpr double kQf = 0.5, kFeatureWidthDeg = 0.082;

// Scales positive taps to sum 1 and negative taps to sum -1 (a part that underflowed to
// nothing stays zero).
void normalizeSigned(std::vector<double>& k) {
    double pos = 0, neg = 0;
    for (double v : k)
        (v > 0 ? pos : neg) += std::abs(v);
    for (double& v : k) {
        const double s = v > 0 ? pos : neg;
        v = s > 0 ? v / s : 0.0;
    }
}

// The 2D detectors d(x) g(y) have the sign of d(x) alone, so normalizing the 1D derivative
// factor (signed) and the Gaussian factor (to sum 1) normalizes the 2D kernel the same way.
struct FeatureKernels {
    std::vector<double> smooth, edge, point;
};

FeatureKernels featureKernels(double ppd) {
    const double sigma = 0.5 * kFeatureWidthDeg * ppd;
    const int radius = int(std::ceil(3 * sigma));
    FeatureKernels k;
    double sum = 0;
    for (int i = -radius; i <= radius; ++i) {
        const double g = std::exp(-double(i) * i / (2 * sigma * sigma));
        k.smooth.push_back(g);
        k.edge.push_back(-i * g);
        k.point.push_back((double(i) * i / (sigma * sigma) - 1) * g);
        sum += g;
    }
    for (double& v : k.smooth)
        v /= sum;
    normalizeSigned(k.edge);
    normalizeSigned(k.point);
    return k;
}

} // namespace

Plane luminance(const image::Image8& img) {
    const double whiteY = colour::whitePoint()[1];
    Plane out{img.width, img.height, std::vector<double>(size_t(img.width) * img.height)};
    for (size_t i = 0; i < out.v.size(); ++i) {
        const colour::Vec3 rgb{colour::srgbToLinear(img.pixels[i * 4] / 255.0),
                               colour::srgbToLinear(img.pixels[i * 4 + 1] / 255.0),
                               colour::srgbToLinear(img.pixels[i * 4 + 2] / 255.0)};
        out.v[i] = colour::linearRgbToXyz(rgb)[1] / whiteY;
    }
    return out;
}

FeatureResponse featureResponse(const Plane& lum, double ppd) {
    const FeatureKernels k = featureKernels(ppd);
    // |(x response, y response)|: the detector along x smoothed along y, and transposed.
    auto magnitude = [&](const std::vector<double>& detector) {
        Plane gx = convolveSeparable(lum, detector, k.smooth);
        const Plane gy = convolveSeparable(lum, k.smooth, detector);
        for (size_t i = 0; i < gx.v.size(); ++i)
            gx.v[i] = std::hypot(gx.v[i], gy.v[i]);
        return gx;
    };
    return {magnitude(k.edge), magnitude(k.point)};
}

Plane featureError(const image::Image8& test, const image::Image8& reference, double ppd) {
    const FeatureResponse t = featureResponse(luminance(test), ppd);
    const FeatureResponse r = featureResponse(luminance(reference), ppd);
    Plane out{test.width, test.height, std::vector<double>(t.edges.v.size())};
    for (size_t i = 0; i < out.v.size(); ++i) {
        const double d = std::max(std::abs(t.edges.v[i] - r.edges.v[i]),
                                  std::abs(t.points.v[i] - r.points.v[i]));
        out.v[i] = std::pow(d / std::sqrt(2.0), kQf);
    }
    return out;
}

} // namespace pb::metrics::flip
