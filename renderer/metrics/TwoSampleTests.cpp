// Two-sample tests for "did the distribution change": Mann-Whitney U (location) and
// Kolmogorov-Smirnov (any difference in shape), the pair Chromium's Pinpoint takes the
// minimum of.
#include "metrics/RankDistributions.h"
#include "metrics/Statistics.h"
#include "metrics/StatsInput.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pb::stats {
namespace {

constexpr size_t kExactTableMax = 50;       // per sample
constexpr double kExactKsMaxProduct = 1e6;  // m * n lattice cells

struct RankSums {
    double uA = 0;      // pairs a > b, ties counted 1/2
    double tieTerm = 0; // sum over tie groups of t^3 - t
    bool hasTies = false;
};

RankSums rankSums(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<std::pair<double, int>> all; // value, 0 = a / 1 = b
    for (double v : a)
        all.push_back({v, 0});
    for (double v : b)
        all.push_back({v, 1});
    std::sort(all.begin(), all.end());
    RankSums r;
    double rankSumA = 0;
    for (size_t i = 0; i < all.size();) {
        size_t j = i;
        while (j < all.size() && all[j].first == all[i].first)
            ++j;
        const double midrank = 0.5 * double(i + 1 + j); // ranks i+1 .. j
        const double t = double(j - i);
        if (t > 1) {
            r.hasTies = true;
            r.tieTerm += t * t * t - t;
        }
        for (size_t k = i; k < j; ++k)
            if (all[k].second == 0) rankSumA += midrank;
        i = j;
    }
    const double m = double(a.size());
    r.uA = rankSumA - m * (m + 1) / 2;
    return r;
}

// Kolmogorov's limiting distribution Q(lambda) = 2 sum (-1)^(k-1) exp(-2 k^2 lambda^2).
double kolmogorovQ(double lambda) {
    if (lambda < 0.2) return 1.0; // the series converges slowly there; Q(0.2) = 1 - 1e-10
    double sum = 0;
    for (int k = 1; k <= 100; ++k) {
        const double term = std::exp(-2.0 * k * k * lambda * lambda);
        sum += (k % 2 ? term : -term);
        if (term < 1e-17) break;
    }
    return std::clamp(2 * sum, 0.0, 1.0);
}

} // namespace

double mannWhitneyP(const std::vector<double>& a, const std::vector<double>& b) {
    detail::requireSample("mannWhitneyP", "a", a);
    detail::requireSample("mannWhitneyP", "b", b);
    const size_t m = a.size(), n = b.size();
    const RankSums r = rankSums(a, b);
    if (!r.hasTies && m <= kExactTableMax && n <= kExactTableMax) {
        const std::vector<double> cdf = detail::mannWhitneyCdf(int(m), int(n));
        const size_t u = size_t(std::llround(r.uA));
        // Symmetric null distribution: P(U >= u) = P(U <= mn - u).
        return std::min(1.0, 2 * std::min(cdf[u], cdf[m * n - u]));
    }
    const double mn = double(m) * double(n), total = double(m + n);
    const double variance = mn / 12 * ((total + 1) - r.tieTerm / (total * (total - 1)));
    if (variance <= 0) return 1.0; // every value the same: no evidence of any difference
    const double z = std::max(0.0, std::abs(r.uA - mn / 2) - 0.5) / std::sqrt(variance);
    return std::min(1.0, std::erfc(z / std::sqrt(2.0)));
}

double kolmogorovSmirnovP(const std::vector<double>& a, const std::vector<double>& b) {
    detail::requireSample("kolmogorovSmirnovP", "a", a);
    detail::requireSample("kolmogorovSmirnovP", "b", b);
    std::vector<double> x = a, y = b;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    const long long m = (long long)x.size(), n = (long long)y.size();
    // D = max |i/m - j/n| over the steps of both empirical CDFs, kept as the integer
    // max |i n - j m| so the exact count below compares without rounding.
    long long dScaled = 0;
    for (size_t i = 0, j = 0; i < x.size() || j < y.size();) {
        const double v = j >= y.size() || (i < x.size() && x[i] <= y[j]) ? x[i] : y[j];
        while (i < x.size() && x[i] == v)
            ++i; // ties move together
        while (j < y.size() && y[j] == v)
            ++j;
        dScaled = std::max(dScaled, std::llabs((long long)i * n - (long long)j * m));
    }
    if (dScaled == 0) return 1.0;
    if (double(m) * double(n) <= kExactKsMaxProduct) {
        // Every interleaving of the two sorted samples is equally likely under H0: walk the
        // m x n lattice with the uniform-path transition probabilities and add up the
        // probability of first reaching a cell with |i n - j m| >= D m n (Hodges 1957).
        // Summing the escaping mass keeps small p-values accurate.
        std::vector<double> row(size_t(n) + 1, 0.0), next(size_t(n) + 1, 0.0);
        row[0] = 1.0;
        double escaped = 0;
        for (long long i = 0; i <= m; ++i) {
            std::fill(next.begin(), next.end(), 0.0);
            for (long long j = 0; j <= n; ++j) {
                const double mass = row[size_t(j)];
                if (mass == 0) continue;
                const double left = double(m - i) + double(n - j);
                if (left == 0) continue;
                auto move = [&](long long ti, long long tj, double share, double& target) {
                    if (share == 0) return;
                    if (std::llabs(ti * n - tj * m) >= dScaled)
                        escaped += mass * share;
                    else
                        target += mass * share;
                };
                if (j < n) move(i, j + 1, double(n - j) / left, row[size_t(j) + 1]);
                if (i < m) move(i + 1, j, double(m - i) / left, next[size_t(j)]);
            }
            std::swap(row, next);
        }
        return std::min(1.0, escaped);
    }
    const double d = double(dScaled) / (double(m) * double(n));
    const double en = std::sqrt(double(m) * double(n) / double(m + n));
    return kolmogorovQ((en + 0.12 + 0.11 / en) * d); // Stephens (1970) correction
}

} // namespace pb::stats
