// LDR-FLIP colour pipeline (steps 1-6 of the list in Flip.cpp).
#include "metrics/ColourSpaces.h"
#include "metrics/FlipStages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pb::metrics::flip {
namespace {

using colour::Vec3;
constexpr double kPi = std::numbers::pi;
constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;

struct CsfChannel {
    double a1, b1, a2, b2;
};
constexpr std::array<CsfChannel, 3> kCsf{{{1.0, 0.0047, 0.0, 1e-5},    // achromatic (Y)
                                          {1.0, 0.0053, 0.0, 1e-5},    // red-green (Cx)
                                          {34.1, 0.04, 13.5, 0.025}}}; // blue-yellow (Cz)

// One Gaussian term of a CSF filter: its 1D normalized taps and its share of the 2D sum.
struct CsfTerm {
    std::vector<double> taps;
    double share = 0;
};

std::vector<CsfTerm> csfTerms(const CsfChannel& c, double ppd, int radius) {
    std::vector<CsfTerm> terms;
    double total = 0;
    for (auto [a, b] : {std::pair{c.a1, c.b1}, std::pair{c.a2, c.b2}}) {
        if (a == 0) continue;
        CsfTerm t;
        double sum = 0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd; // degrees
            t.taps.push_back(std::exp(-kPi * kPi * x * x / b));
            sum += t.taps.back();
        }
        for (double& v : t.taps)
            v /= sum;
        // The 2D term is a sqrt(pi/b) g(x) g(y); its sum over the square is that times sum^2.
        t.share = a * std::sqrt(kPi / b) * sum * sum;
        total += t.share;
        terms.push_back(std::move(t));
    }
    for (auto& t : terms)
        t.share /= total;
    return terms;
}

Plane csfFilter(const Plane& in, const CsfChannel& c, double ppd, int radius) {
    Plane out{in.width, in.height, std::vector<double>(in.v.size(), 0.0)};
    for (const CsfTerm& t : csfTerms(c, ppd, radius)) {
        const Plane f = convolveSeparable(in, t.taps, t.taps);
        for (size_t i = 0; i < out.v.size(); ++i)
            out.v[i] += t.share * f.v[i];
    }
    return out;
}

Vec3 huntLab(const Vec3& lab) {
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

double hyab(const Vec3& p, const Vec3& q) {
    return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

// Steps 3-4: filtered YCxCz -> clamped linear RGB -> Hunt-adjusted CIELAB.
std::vector<Vec3> huntLabOf(const std::array<Plane, 3>& opponent) {
    std::vector<Vec3> lab(opponent[0].v.size());
    for (size_t i = 0; i < lab.size(); ++i) {
        Vec3 rgb = colour::xyzToLinearRgb(
            colour::ycxczToXyz({opponent[0].v[i], opponent[1].v[i], opponent[2].v[i]}));
        for (double& v : rgb)
            v = std::clamp(v, 0.0, 1.0);
        lab[i] = huntLab(colour::xyzToLab(colour::linearRgbToXyz(rgb)));
    }
    return lab;
}

// Largest colour error the redistribution expects: pure green vs pure blue.
double maxColourError() {
    const Vec3 green = huntLab(colour::xyzToLab(colour::linearRgbToXyz({0, 1, 0})));
    const Vec3 blue = huntLab(colour::xyzToLab(colour::linearRgbToXyz({0, 0, 1})));
    return std::pow(hyab(green, blue), kQc);
}

double redistribute(double hyabDistance, double cmax) {
    const double e = std::pow(hyabDistance, kQc);
    const double knee = kPc * cmax;
    return e < knee ? e * kPt / knee : kPt + (e - knee) / (cmax - knee) * (1 - kPt);
}

} // namespace

std::array<Plane, 3> csfFilteredOpponent(const image::Image8& img, double ppd) {
    const int w = img.width, h = img.height;
    const size_t n = size_t(w) * h;
    std::array<Plane, 3> opponent;
    for (auto& p : opponent)
        p = Plane{w, h, std::vector<double>(n)};
    for (size_t i = 0; i < n; ++i) {
        const Vec3 rgb{colour::srgbToLinear(img.pixels[i * 4] / 255.0),
                       colour::srgbToLinear(img.pixels[i * 4 + 1] / 255.0),
                       colour::srgbToLinear(img.pixels[i * 4 + 2] / 255.0)};
        const Vec3 ycxcz = colour::xyzToYcxcz(colour::linearRgbToXyz(rgb));
        for (size_t c = 0; c < 3; ++c)
            opponent[c].v[i] = ycxcz[c];
    }
    double bMax = 0;
    for (const auto& c : kCsf)
        bMax = std::max({bMax, c.b1, c.b2});
    const int radius = int(std::ceil(3 * std::sqrt(bMax / (2 * kPi * kPi)) * ppd));
    for (size_t c = 0; c < 3; ++c)
        opponent[c] = csfFilter(opponent[c], kCsf[c], ppd, radius);
    return opponent;
}

Plane colourError(const image::Image8& test, const image::Image8& reference, double ppd) {
    const std::vector<Vec3> t = huntLabOf(csfFilteredOpponent(test, ppd));
    const std::vector<Vec3> r = huntLabOf(csfFilteredOpponent(reference, ppd));
    const double cmax = maxColourError();
    Plane out{test.width, test.height, std::vector<double>(t.size())};
    for (size_t i = 0; i < t.size(); ++i)
        out.v[i] = redistribute(hyab(t[i], r[i]), cmax);
    return out;
}

} // namespace pb::metrics::flip
