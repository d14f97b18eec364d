#include "metrics/RankDistributions.h"

#include "metrics/StatsInput.h"

#include <algorithm>
#include <cmath>

namespace pb::stats::detail {

std::vector<double> signedRankCdf(int n) {
    // Under H0 each rank r carries a + sign with probability 1/2, independently: the
    // distribution of T = sum of + ranks grows one rank at a time.
    const size_t maxT = size_t(n) * (n + 1) / 2;
    std::vector<double> pmf(maxT + 1, 0.0);
    pmf[0] = 1.0;
    size_t reach = 0; // largest T possible with the ranks so far
    for (int r = 1; r <= n; ++r) {
        reach += size_t(r);
        // Downwards, so pmf[t - r] still holds the previous rank's value.
        for (size_t t = reach + 1; t-- > 0;)
            pmf[t] = 0.5 * (pmf[t] + (t >= size_t(r) ? pmf[t - size_t(r)] : 0.0));
    }
    std::vector<double> cdf(maxT + 1);
    double sum = 0;
    for (size_t t = 0; t <= maxT; ++t)
        cdf[t] = (sum += pmf[t]);
    return cdf;
}

std::vector<double> mannWhitneyCdf(int m, int n) {
    // Of i + j values the largest belongs to the first sample with probability i/(i+j) and then
    // beats all j of the second: P_ij(u) = i/(i+j) P_(i-1)j(u-j) + j/(i+j) P_i(j-1)(u).
    // Probabilities (not counts) keep every term positive and within double range.
    std::vector<std::vector<double>> prev(size_t(n) + 1), cur(size_t(n) + 1);
    for (auto& p : prev)
        p = {1.0}; // i = 0: U = 0
    for (int i = 1; i <= m; ++i) {
        cur[0] = {1.0};
        for (int j = 1; j <= n; ++j) {
            std::vector<double> p(size_t(i) * j + 1, 0.0);
            const double fromA = double(i) / (i + j), fromB = double(j) / (i + j);
            for (size_t u = 0; u < prev[size_t(j)].size(); ++u)
                p[u + size_t(j)] += fromA * prev[size_t(j)][u];
            for (size_t u = 0; u < cur[size_t(j) - 1].size(); ++u)
                p[u] += fromB * cur[size_t(j) - 1][u];
            cur[size_t(j)] = std::move(p);
        }
        std::swap(prev, cur);
    }
    std::vector<double> cdf = prev[size_t(n)];
    for (size_t u = 1; u < cdf.size(); ++u)
        cdf[u] += cdf[u - 1];
    return cdf;
}

RankInterval intervalFromCdf(const std::vector<double>& cdf, double confidence) {
    const double tail = (1 - confidence) / 2;
    RankInterval r;
    // P(S <= k-1) = cdf[k-1]; the symmetric interval needs k <= (N+1)/2 with N = cdf.size()-1.
    while (r.k < cdf.size() / 2 && cdf[r.k] <= tail * (1 + 1e-12))
        ++r.k;
    r.coverage = 1 - 2 * cdf[r.k - 1];
    return r;
}

RankInterval intervalFromNormal(double mean, double sd, size_t candidates, double confidence) {
    const double z = normalQuantile(1 - (1 - confidence) / 2);
    // P(S <= k-1) ~ Phi((k - 1 + 0.5 - mean) / sd) <= tail  <=>  k <= mean + 0.5 - z sd.
    const double k = std::floor(mean + 0.5 - z * sd);
    RankInterval r;
    r.k = size_t(std::clamp(k, 1.0, double((candidates + 1) / 2)));
    r.coverage = 1 - 2 * normalCdf((double(r.k) - 0.5 - mean) / sd);
    return r;
}

} // namespace pb::stats::detail
