#include "Spread.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pb::bench {

double percentile(std::vector<double> samples, double q) {
    if (samples.empty()) return NAN;
    std::sort(samples.begin(), samples.end());
    const double h = (double(samples.size()) - 1.0) * q;
    const size_t lo = size_t(std::floor(h));
    const size_t hi = std::min(lo + 1, samples.size() - 1);
    return samples[lo] + (h - double(lo)) * (samples[hi] - samples[lo]);
}

namespace {
double variance(const std::vector<double>& x) {
    if (x.size() < 2) return NAN;
    double mean = 0;
    for (double v : x)
        mean += v;
    mean /= double(x.size());
    double m2 = 0;
    for (double v : x)
        m2 += (v - mean) * (v - mean);
    return m2 / double(x.size() - 1);
}
} // namespace

double bimodalityCoefficient(const std::vector<double>& x) {
    const double n = double(x.size());
    if (x.size() < 4) return NAN;
    double mean = 0;
    for (double v : x)
        mean += v;
    mean /= n;
    double m2 = 0, m3 = 0, m4 = 0;
    for (double v : x) {
        const double d = v - mean;
        m2 += d * d;
        m3 += d * d * d;
        m4 += d * d * d * d;
    }
    m2 /= n;
    m3 /= n;
    m4 /= n;
    if (!(m2 > 0)) return NAN;
    // Sample skewness and excess kurtosis with the usual small-sample corrections (SAS, SPSS).
    const double g1 = m3 / std::pow(m2, 1.5), g2 = m4 / (m2 * m2) - 3.0;
    const double skew = g1 * std::sqrt(n * (n - 1)) / (n - 2);
    const double kurt = ((n + 1) * g2 + 6) * (n - 1) / ((n - 2) * (n - 3));
    return (skew * skew + 1) / (kurt + 3 * (n - 1) * (n - 1) / ((n - 2) * (n - 3)));
}

std::string noiseFlags(const VariantResult& off, const VariantResult& on) {
    std::string out;
    auto add = [&](const std::string& flag) { out += (out.empty() ? "" : "; ") + flag; };
    const bool offBimodal = bimodalityCoefficient(off.frameSamples) > kBimodalAbove;
    const bool onBimodal = bimodalityCoefficient(on.frameSamples) > kBimodalAbove;
    if (offBimodal || onBimodal)
        add(std::string("bimodal: ") + (offBimodal && onBimodal ? "both" : offBimodal ? "off" : "on"));
    const double a = variance(off.frameSamples), b = variance(on.frameSamples);
    if (a > 0 && b > 0) {
        const double ratio = std::max(a, b) / std::min(a, b);
        if (ratio > kVarianceRatioFlag) {
            char text[64];
            std::snprintf(text, sizeof text, "variance x%.1f (%s)", ratio, b > a ? "up" : "down");
            add(text);
        }
    }
    return out;
}

} // namespace pb::bench
