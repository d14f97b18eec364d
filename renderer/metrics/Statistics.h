#pragma once
// Robust statistics for benchmark rounds: medians with confidence intervals, shift estimates
// (Hodges-Lehmann) with rank-based intervals, and two-sample tests (Mann-Whitney U,
// Kolmogorov-Smirnov) as the CI timing gate uses them. Every function throws pb::Error for an
// empty sample, a non-finite value, or a confidence outside (0,1).
#include <cstddef>
#include <vector>

namespace pb::stats {

struct Summary {
    size_t n = 0;
    double median = 0, min = 0, max = 0, mean = 0, q1 = 0, q3 = 0, iqr = 0, ciLow = 0,
           ciHigh = 0; // ci: of the median
    // The coverage the interval really has: order statistics give discrete levels, so it is
    // >= the confidence asked for, except for tiny n where even [min, max] falls short.
    double ciLevel = 0;
};

// Quantiles interpolate linearly between order statistics (Hyndman & Fan type 7, the default
// of R and NumPy). The median's interval is distribution-free, from order statistics: the
// symmetric pair [x_(l), x_(n+1-l)] whose binomial(n, 1/2) coverage is >= `confidence`.
Summary summarize(std::vector<double> samples, double confidence = 0.95);

struct Shift {
    double estimate = 0, ciLow = 0, ciHigh = 0;
    double ciLevel = 0; // the interval's real coverage (discrete, see Summary::ciLevel)
};

// b - a for interleaved rounds (A B A B): Hodges-Lehmann estimate of the paired differences
// (median of the Walsh averages), interval from the Wilcoxon signed-rank distribution (exact
// for n <= 100, normal approximation above). a and b must have the same size.
Shift pairedShift(const std::vector<double>& a, const std::vector<double>& b,
                  double confidence = 0.95);

// Two-sample Hodges-Lehmann shift b - a (median of all b_j - a_i), interval from the
// Mann-Whitney distribution (exact when both samples have <= 50 values, normal above).
Shift hodgesLehmannShift(const std::vector<double>& a, const std::vector<double>& b,
                         double confidence = 0.95);

// Two-sided Mann-Whitney U p-value: exact when both samples have <= 50 values and there are
// no ties, otherwise the normal approximation with tie and continuity correction.
double mannWhitneyP(const std::vector<double>& a, const std::vector<double>& b);

// Two-sample two-sided Kolmogorov-Smirnov p-value: exact (lattice paths) when m*n <= 1e6,
// otherwise the asymptotic Kolmogorov distribution with Stephens' small-sample correction.
double kolmogorovSmirnovP(const std::vector<double>& a, const std::vector<double>& b);

} // namespace pb::stats
