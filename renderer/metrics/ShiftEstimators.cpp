// Hodges-Lehmann shift estimates with intervals from inverting the rank tests: the interval's
// ends are order statistics of the candidate shifts (Walsh averages or pairwise differences)
// at ranks taken from the test statistic's null distribution (Hollander & Wolfe,
// "Nonparametric Statistical Methods", sections 3.2 and 4.3).
#include "core/Error.h"
#include "metrics/RankDistributions.h"
#include "metrics/Statistics.h"
#include "metrics/StatsInput.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pb::stats {
namespace {

constexpr int kExactSignedRankMax = 100; // pairs; the exact table costs O(n^3)
constexpr int kExactMannWhitneyMax = 50; // per sample; the exact table costs O(m^2 n^2)

double medianSorted(const std::vector<double>& s) {
    const size_t n = s.size();
    return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
}

Shift fromCandidates(std::vector<double> candidates, const detail::RankInterval& r) {
    std::sort(candidates.begin(), candidates.end());
    Shift s;
    s.estimate = medianSorted(candidates);
    s.ciLow = candidates[r.k - 1];
    s.ciHigh = candidates[candidates.size() - r.k];
    s.ciLevel = r.coverage;
    return s;
}

} // namespace

Shift pairedShift(const std::vector<double>& a, const std::vector<double>& b, double confidence) {
    detail::requireSample("pairedShift", "a", a);
    detail::requireSample("pairedShift", "b", b);
    detail::requireConfidence("pairedShift", confidence);
    if (a.size() != b.size())
        throw Error("pairedShift: the samples must pair up, got " + std::to_string(a.size()) +
                    " and " + std::to_string(b.size()) + " values");
    const size_t n = a.size();
    std::vector<double> d(n);
    for (size_t i = 0; i < n; ++i)
        d[i] = b[i] - a[i];
    std::vector<double> walsh;
    walsh.reserve(n * (n + 1) / 2);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i; j < n; ++j)
            walsh.push_back(0.5 * (d[i] + d[j]));
    const detail::RankInterval r =
        n <= size_t(kExactSignedRankMax)
            ? detail::intervalFromCdf(detail::signedRankCdf(int(n)), confidence)
            : detail::intervalFromNormal(double(n) * (n + 1) / 4,
                                         std::sqrt(double(n) * (n + 1) * (2 * n + 1) / 24),
                                         walsh.size(), confidence);
    return fromCandidates(std::move(walsh), r);
}

Shift hodgesLehmannShift(const std::vector<double>& a, const std::vector<double>& b,
                         double confidence) {
    detail::requireSample("hodgesLehmannShift", "a", a);
    detail::requireSample("hodgesLehmannShift", "b", b);
    detail::requireConfidence("hodgesLehmannShift", confidence);
    const size_t m = a.size(), n = b.size();
    std::vector<double> diffs;
    diffs.reserve(m * n);
    for (double x : a)
        for (double y : b)
            diffs.push_back(y - x);
    const bool exact = m <= size_t(kExactMannWhitneyMax) && n <= size_t(kExactMannWhitneyMax);
    const detail::RankInterval r =
        exact ? detail::intervalFromCdf(detail::mannWhitneyCdf(int(m), int(n)), confidence)
              : detail::intervalFromNormal(double(m) * n / 2,
                                           std::sqrt(double(m) * n * (m + n + 1) / 12),
                                           diffs.size(), confidence);
    return fromCandidates(std::move(diffs), r);
}

} // namespace pb::stats
