// Median, quartiles and a distribution-free interval for the median.
#include "metrics/RankDistributions.h"
#include "metrics/Statistics.h"
#include "metrics/StatsInput.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pb::stats {
namespace {

// Hyndman & Fan type 7 on sorted data: h = (n-1) p, interpolate between floor(h) and ceil(h).
double quantileSorted(const std::vector<double>& s, double p) {
    const double h = (double(s.size()) - 1) * p;
    const size_t lo = size_t(std::floor(h));
    const size_t hi = std::min(lo + 1, s.size() - 1);
    return s[lo] + (h - double(lo)) * (s[hi] - s[lo]);
}

// P(B <= k) for B ~ binomial(n, 1/2), k = 0..n (log-space terms: n may be large).
std::vector<double> binomialHalfCdf(size_t n) {
    std::vector<double> cdf(n + 1);
    double sum = 0;
    const double logHalfN = double(n) * std::log(0.5);
    for (size_t k = 0; k <= n; ++k) {
        const double logChoose = std::lgamma(double(n) + 1) - std::lgamma(double(k) + 1) -
                                 std::lgamma(double(n - k) + 1);
        cdf[k] = (sum += std::exp(logChoose + logHalfN));
    }
    return cdf;
}

} // namespace

Summary summarize(std::vector<double> samples, double confidence) {
    detail::requireSample("summarize", "samples", samples);
    detail::requireConfidence("summarize", confidence);
    std::sort(samples.begin(), samples.end());
    Summary s;
    s.n = samples.size();
    s.min = samples.front();
    s.max = samples.back();
    s.mean = std::accumulate(samples.begin(), samples.end(), 0.0) / double(s.n);
    s.median = quantileSorted(samples, 0.5);
    s.q1 = quantileSorted(samples, 0.25);
    s.q3 = quantileSorted(samples, 0.75);
    s.iqr = s.q3 - s.q1;
    // The count of samples below the true median is binomial(n, 1/2) whatever the
    // distribution, so [x_(k), x_(n+1-k)] covers it with probability 1 - 2 P(B <= k-1).
    const detail::RankInterval r = detail::intervalFromCdf(binomialHalfCdf(s.n), confidence);
    s.ciLow = samples[r.k - 1];
    s.ciHigh = samples[s.n - r.k];
    s.ciLevel = r.coverage;
    return s;
}

} // namespace pb::stats
