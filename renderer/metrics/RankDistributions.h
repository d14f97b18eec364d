#pragma once
// Exact null distributions of the rank statistics (as cumulative probabilities) and the rule
// that turns one into a confidence interval's rank.
#include <cstddef>
#include <vector>

namespace pb::stats::detail {

// P(T <= t), t = 0 .. n(n+1)/2, for the Wilcoxon signed-rank statistic T of n pairs.
std::vector<double> signedRankCdf(int n);
// P(U <= u), u = 0 .. m n, for the Mann-Whitney statistic U (pairs where the first sample is
// larger) of samples of sizes m and n without ties.
std::vector<double> mannWhitneyCdf(int m, int n);

// The interval [x_(k), x_(N+1-k)] (1-based order statistics of N candidates) whose coverage is
// 1 - 2 P(S <= k-1): k is the largest rank with P(S <= k-1) <= (1 - confidence)/2, at least 1.
struct RankInterval {
    size_t k = 1;
    double coverage = 0;
};
RankInterval intervalFromCdf(const std::vector<double>& cdf, double confidence);
// The same from a normal approximation of S with this mean and standard deviation
// (continuity-corrected), for N candidates.
RankInterval intervalFromNormal(double mean, double sd, size_t candidates, double confidence);

} // namespace pb::stats::detail
