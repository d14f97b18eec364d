// Statistics against textbook and enumerated values: quantiles on known data, order-statistic
// and rank-test intervals at their tabulated critical values, exact p-values counted by hand.
#include "metrics/Statistics.h"
#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace pb;

namespace {

// Uniform (0,1) from mt19937's fully specified output (std::uniform_real_distribution is
// implementation-defined).
double uniform01(std::mt19937& rng) {
    return (double(rng()) + 0.5) / 4294967296.0;
}

std::vector<double> sortedWalshAverages(const std::vector<double>& d) {
    std::vector<double> w;
    for (size_t i = 0; i < d.size(); ++i)
        for (size_t j = i; j < d.size(); ++j)
            w.push_back(0.5 * (d[i] + d[j]));
    std::sort(w.begin(), w.end());
    return w;
}

} // namespace

// ---- summarize ----

TEST(Summarize, QuantilesOfOneToNine) {
    // Type 7: q(p) at position (n-1) p = 2, 4, 6 -> 3, 5, 7.
    const stats::Summary s = stats::summarize({9, 1, 8, 2, 7, 3, 6, 4, 5});
    EXPECT_EQ(s.n, 9u);
    EXPECT_DOUBLE_EQ(s.median, 5);
    EXPECT_DOUBLE_EQ(s.q1, 3);
    EXPECT_DOUBLE_EQ(s.q3, 7);
    EXPECT_DOUBLE_EQ(s.iqr, 4);
    EXPECT_DOUBLE_EQ(s.min, 1);
    EXPECT_DOUBLE_EQ(s.max, 9);
    EXPECT_DOUBLE_EQ(s.mean, 5);
    // Binomial(9, 1/2): P(B <= 1) = 10/512 <= 0.025 < P(B <= 2) = 46/512, so the interval is
    // [x(2), x(8)] = [2, 8] with coverage 1 - 20/512.
    EXPECT_DOUBLE_EQ(s.ciLow, 2);
    EXPECT_DOUBLE_EQ(s.ciHigh, 8);
    EXPECT_NEAR(s.ciLevel, 1 - 20.0 / 512, 1e-12);
}

TEST(Summarize, InterpolatesBetweenOrderStatistics) {
    // n = 4: positions 0.75, 1.5, 2.25 -> 1.75, 2.5, 3.25. P(B <= 0) = 1/16 > 0.025: even
    // [min, max] covers only 1 - 2/16 = 87.5%, which ciLevel reports.
    const stats::Summary s = stats::summarize({4, 1, 3, 2});
    EXPECT_DOUBLE_EQ(s.median, 2.5);
    EXPECT_DOUBLE_EQ(s.q1, 1.75);
    EXPECT_DOUBLE_EQ(s.q3, 3.25);
    EXPECT_DOUBLE_EQ(s.ciLow, 1);
    EXPECT_DOUBLE_EQ(s.ciHigh, 4);
    EXPECT_NEAR(s.ciLevel, 0.875, 1e-12);
}

TEST(Summarize, IntervalRankFollowsTheConfidence) {
    std::vector<double> v;
    for (int i = 1; i <= 10; ++i)
        v.push_back(10.0 * i);
    // 95%: P(B <= 1) = 11/1024 <= 0.025 < P(B <= 2) = 56/1024 -> [x(2), x(9)].
    const stats::Summary s95 = stats::summarize(v);
    EXPECT_DOUBLE_EQ(s95.ciLow, 20);
    EXPECT_DOUBLE_EQ(s95.ciHigh, 90);
    EXPECT_NEAR(s95.ciLevel, 1 - 22.0 / 1024, 1e-12);
    // 50%: P(B <= 3) = 176/1024 <= 0.25 < P(B <= 4) = 386/1024 -> [x(4), x(7)].
    const stats::Summary s50 = stats::summarize(v, 0.5);
    EXPECT_DOUBLE_EQ(s50.ciLow, 40);
    EXPECT_DOUBLE_EQ(s50.ciHigh, 70);
    EXPECT_NEAR(s50.ciLevel, 1 - 352.0 / 1024, 1e-12);
}

TEST(Summarize, IntervalCoversTheTrueMedianAsOftenAsItSays) {
    // Symmetric uniform(0,1) samples of 15: true median 0.5. 4000 seeded trials; the standard
    // error of the observed coverage is about 0.003.
    std::mt19937 rng(12345);
    int covered = 0;
    const int trials = 4000;
    double level = 0;
    for (int t = 0; t < trials; ++t) {
        std::vector<double> v(15);
        for (double& x : v)
            x = uniform01(rng);
        const stats::Summary s = stats::summarize(v);
        level = s.ciLevel;
        covered += s.ciLow <= 0.5 && 0.5 <= s.ciHigh;
    }
    // P(B <= 3) = 576/32768 for n = 15.
    EXPECT_NEAR(level, 1 - 2 * 576.0 / 32768, 1e-12);
    EXPECT_NEAR(double(covered) / trials, level, 0.015);
}

TEST(Summarize, RejectsBadInput) {
    EXPECT_THROW(stats::summarize({}), Error);
    EXPECT_THROW(stats::summarize({1, std::nan(""), 2}), Error);
    EXPECT_THROW(stats::summarize({1, 2}, 0.0), Error);
    EXPECT_THROW(stats::summarize({1, 2}, 1.0), Error);
    EXPECT_THROW(stats::summarize({1, 2}, std::nan("")), Error);
}

// ---- paired shift ----

TEST(PairedShift, RecoversAKnownShift) {
    std::mt19937 rng(7);
    std::vector<double> a, b;
    for (int i = 0; i < 21; ++i) {
        const double base = 10 + 5 * uniform01(rng); // round-to-round drift, shared by the pair
        a.push_back(base);
        b.push_back(base + 3 + 0.2 * (uniform01(rng) - 0.5));
    }
    const stats::Shift s = stats::pairedShift(a, b);
    EXPECT_NEAR(s.estimate, 3, 0.1);
    EXPECT_LT(s.ciLow, 3);
    EXPECT_GT(s.ciHigh, 3);
    EXPECT_LT(s.ciHigh - s.ciLow, 0.25) << "pairing removes the shared drift";
    EXPECT_GE(s.ciLevel, 0.95);
}

TEST(PairedShift, IntervalAtTheTabulatedSignedRankCriticalValues) {
    // Two-sided 5% critical values of the Wilcoxon signed-rank T (tables, e.g. Hollander & Wolfe):
    // n = 10: 8, n = 20: 52. The interval is [W(c+1), W(M-c)] of the M = n(n+1)/2 sorted Walsh
    // averages.
    for (auto [n, critical] : {std::pair{10, 8}, std::pair{20, 52}}) {
        std::vector<double> a(size_t(n), 0.0), b;
        for (int i = 1; i <= n; ++i)
            b.push_back(std::pow(double(i), 1.3) - 4); // distinct
        const std::vector<double> w = sortedWalshAverages(b);
        const stats::Shift s = stats::pairedShift(a, b);
        EXPECT_DOUBLE_EQ(s.ciLow, w[size_t(critical)]) << n;
        EXPECT_DOUBLE_EQ(s.ciHigh, w[w.size() - 1 - size_t(critical)]) << n;
        const size_t m = w.size();
        EXPECT_DOUBLE_EQ(s.estimate, m % 2 ? w[m / 2] : 0.5 * (w[m / 2 - 1] + w[m / 2])) << n;
    }
    // n = 10: P(T <= 8) = 25/1024, so the coverage is 1 - 50/1024.
    std::vector<double> a(10, 0.0), b{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    EXPECT_NEAR(stats::pairedShift(a, b).ciLevel, 1 - 50.0 / 1024, 1e-12);
}

TEST(PairedShift, TinySampleFallsBackToTheFullRange) {
    // n = 5: P(T <= 0) = 1/32 > 0.025, so [min, max] of the Walsh averages, coverage 30/32.
    const stats::Shift s = stats::pairedShift({0, 0, 0, 0, 0}, {1, 2, 3, 4, 5});
    EXPECT_DOUBLE_EQ(s.ciLow, 1);
    EXPECT_DOUBLE_EQ(s.ciHigh, 5);
    EXPECT_DOUBLE_EQ(s.estimate, 3);
    EXPECT_DOUBLE_EQ(s.ciLevel, 30.0 / 32);
}

TEST(PairedShift, NormalApproximationForLargeN) {
    std::mt19937 rng(8);
    std::vector<double> a, b;
    for (int i = 0; i < 150; ++i) {
        a.push_back(uniform01(rng));
        b.push_back(uniform01(rng) - 0.25);
    }
    const stats::Shift s = stats::pairedShift(a, b);
    EXPECT_NEAR(s.estimate, -0.25, 0.06);
    EXPECT_LT(s.ciLow, -0.25);
    EXPECT_GT(s.ciHigh, -0.25);
    EXPECT_NEAR(s.ciLevel, 0.95, 0.01);
}

TEST(PairedShift, RejectsUnpairedInput) {
    EXPECT_THROW(stats::pairedShift({1, 2}, {1, 2, 3}), Error);
    EXPECT_THROW(stats::pairedShift({}, {}), Error);
    EXPECT_THROW(stats::pairedShift({1}, {2}, 1.5), Error);
}

// ---- two-sample Hodges-Lehmann ----

TEST(HodgesLehmannShift, EstimateAndTabulatedInterval) {
    // b - a over {1..5} x {3..7}: differences j - i + 2, symmetric around 2.
    EXPECT_DOUBLE_EQ(stats::hodgesLehmannShift({1, 2, 3, 4, 5}, {3, 4, 5, 6, 7}).estimate, 2);
    // m = n = 10: two-sided 5% critical U = 23 (Mann-Whitney tables), so the interval is
    // [D(24), D(77)] of the 100 sorted differences.
    std::vector<double> a, b, d;
    for (int i = 0; i < 10; ++i) {
        a.push_back(i * i * 0.1);
        b.push_back(2 + std::sqrt(double(i)) * 1.7);
    }
    for (double x : a)
        for (double y : b)
            d.push_back(y - x);
    std::sort(d.begin(), d.end());
    const stats::Shift s = stats::hodgesLehmannShift(a, b);
    EXPECT_DOUBLE_EQ(s.ciLow, d[23]);
    EXPECT_DOUBLE_EQ(s.ciHigh, d[76]);
    EXPECT_DOUBLE_EQ(s.estimate, 0.5 * (d[49] + d[50]));
}

TEST(HodgesLehmannShift, RecoversAShiftWithLargeSamples) {
    std::mt19937 rng(9);
    std::vector<double> a(60), b(70);
    for (double& x : a)
        x = uniform01(rng);
    for (double& x : b)
        x = uniform01(rng) + 0.5;
    const stats::Shift s = stats::hodgesLehmannShift(a, b);
    EXPECT_NEAR(s.estimate, 0.5, 0.1);
    EXPECT_LT(s.ciLow, 0.5);
    EXPECT_GT(s.ciHigh, 0.5);
}

// ---- Mann-Whitney ----

TEST(MannWhitney, ExactPValuesCountedByHand) {
    // 3 vs 3: 20 equally likely orderings. Fully separated: U = 0, P(U <= 0) = 1/20,
    // two-sided 0.1.
    EXPECT_NEAR(stats::mannWhitneyP({1, 2, 3}, {4, 5, 6}), 0.1, 1e-12);
    // {1,2,4} vs {3,5,6}: U = 1 (only 4 > 3); U <= 1 for aaabbb and aababb: 2/20, two-sided 0.2.
    EXPECT_NEAR(stats::mannWhitneyP({1, 2, 4}, {3, 5, 6}), 0.2, 1e-12);
    // 4 vs 4 separated: 2/70.
    EXPECT_NEAR(stats::mannWhitneyP({5, 6, 7, 8}, {1, 2, 3, 4}), 2.0 / 70, 1e-12);
}

TEST(MannWhitney, NormalApproximationWithTies) {
    // {1,1,2} vs {2,3,3}: midranks 1.5 1.5 3.5 | 3.5 5.5 5.5; R_a = 6.5, U = 6.5 - 6 = 0.5.
    // mean 4.5; three tie pairs: sum(t^3 - t) = 18; var = 9/12 (7 - 18/30) = 4.8;
    // z = (4 - 0.5) / sqrt(4.8); p = erfc(z / sqrt 2) = 0.1102.
    const double z = 3.5 / std::sqrt(4.8);
    EXPECT_NEAR(stats::mannWhitneyP({1, 1, 2}, {2, 3, 3}), std::erfc(z / std::sqrt(2.0)), 1e-12);
    EXPECT_NEAR(stats::mannWhitneyP({1, 1, 2}, {2, 3, 3}), 0.1102, 1e-4);
}

TEST(MannWhitney, IdenticalSamplesGiveOne) {
    std::vector<double> a;
    for (int i = 0; i < 20; ++i)
        a.push_back(std::sin(i));
    EXPECT_DOUBLE_EQ(stats::mannWhitneyP(a, a), 1.0);
    EXPECT_DOUBLE_EQ(stats::mannWhitneyP({3, 3, 3}, {3, 3}), 1.0);
}

TEST(MannWhitney, SeparatedSamplesGiveTinyP) {
    std::vector<double> a, b, c, d;
    for (int i = 0; i < 30; ++i) {
        a.push_back(i);
        b.push_back(100 + i);
    }
    for (int i = 0; i < 80; ++i) { // normal approximation
        c.push_back(i);
        d.push_back(100 + i);
    }
    EXPECT_LT(stats::mannWhitneyP(a, b), 1e-10);
    EXPECT_DOUBLE_EQ(stats::mannWhitneyP(a, b), stats::mannWhitneyP(b, a));
    EXPECT_LT(stats::mannWhitneyP(c, d), 1e-10);
}

// ---- Kolmogorov-Smirnov ----

TEST(KolmogorovSmirnov, ExactPValuesCountedByHand) {
    // 3 vs 3, separated: D = 1, reached only by the 2 of 20 orderings aaabbb and bbbaaa.
    EXPECT_NEAR(stats::kolmogorovSmirnovP({1, 2, 3}, {4, 5, 6}), 0.1, 1e-12);
    // {1,2,4} vs {3,5,6}: D = 2/3. Orderings keeping |#a - #b| <= 1 on every prefix pair up
    // as (ab|ba)^3: 8 of 20, so P(D >= 2/3) = 12/20.
    EXPECT_NEAR(stats::kolmogorovSmirnovP({1, 2, 4}, {3, 5, 6}), 0.6, 1e-12);
    // 2 vs 3, separated: D = 1 needs aabbb or bbbaa: 2 of 10.
    EXPECT_NEAR(stats::kolmogorovSmirnovP({1, 2}, {3, 4, 5}), 0.2, 1e-12);
    // Perfectly interleaved 4 vs 4: D = 1/4, which every ordering reaches: p = 1.
    EXPECT_NEAR(stats::kolmogorovSmirnovP({1, 3, 5, 7}, {2, 4, 6, 8}), 1.0, 1e-12);
}

TEST(KolmogorovSmirnov, IdenticalAndSeparatedSamples) {
    std::vector<double> a, b;
    for (int i = 0; i < 100; ++i) {
        a.push_back(std::cos(i));
        b.push_back(10 + std::cos(i));
    }
    EXPECT_DOUBLE_EQ(stats::kolmogorovSmirnovP(a, a), 1.0);
    EXPECT_LT(stats::kolmogorovSmirnovP(a, b), 1e-10);
}

TEST(KolmogorovSmirnov, AsymptoticFormulaForLargeSamples) {
    // 1100 vs 1100 (1.21e6 lattice cells, past the exact limit), b = a + 110 on a grid of
    // 0..1099: D = 110/1100 = 0.1. sqrt(en) = sqrt(550); lambda = (sqrt(550) + 0.12 +
    // 0.11/sqrt(550)) * 0.1 = 2.3578; p = 2 exp(-2 lambda^2) - 2 exp(-8 lambda^2) + ...
    std::vector<double> a, b;
    for (int i = 0; i < 1100; ++i) {
        a.push_back(i);
        b.push_back(i + 110);
    }
    const double en = std::sqrt(550.0);
    const double lambda = (en + 0.12 + 0.11 / en) * 0.1;
    const double expected = 2 * std::exp(-2 * lambda * lambda) - 2 * std::exp(-8 * lambda * lambda);
    EXPECT_NEAR(stats::kolmogorovSmirnovP(a, b), expected, expected * 1e-9);
    EXPECT_NEAR(expected, 2.97e-5, 0.05e-5);
}

TEST(TwoSampleTests, RejectEmptyOrNonFinite) {
    EXPECT_THROW(stats::mannWhitneyP({}, {1}), Error);
    EXPECT_THROW(stats::kolmogorovSmirnovP({1}, {}), Error);
    EXPECT_THROW(stats::kolmogorovSmirnovP({1, INFINITY}, {2}), Error);
    EXPECT_THROW(stats::hodgesLehmannShift({1}, {}), Error);
}
