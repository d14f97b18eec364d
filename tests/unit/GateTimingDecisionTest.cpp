// The timing gate's decision (bench/gate/TimingDecision.h) on synthetic samples: Pinpoint's
// p = min(Mann-Whitney, Kolmogorov-Smirnov) with a shift threshold - different only when both
// say so, same when the shift's interval lies inside the threshold, unknown otherwise.
#include "bench/gate/TimingDecision.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <random>

using namespace pb::gate;

namespace {

// n values around `median` with a relative spread (deterministic).
std::vector<double> sample(int n, double median, double spread, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, spread);
    std::vector<double> v;
    for (int i = 0; i < n; ++i)
        v.push_back(median * (1.0 + noise(rng)));
    return v;
}

} // namespace

TEST(GateTimingDecision, ALargeSlowdownIsDifferentAndSlower) {
    const auto a = sample(12, 100.0, 0.01, 1), b = sample(12, 110.0, 0.01, 2);
    const TimingComparison c = compareTiming(a, b, {0.01, 0.03});
    EXPECT_EQ(c.verdict, TimingVerdict::Different);
    EXPECT_TRUE(c.slower());
    EXPECT_LE(c.p, 0.01);
    EXPECT_NEAR(c.shift, 0.10, 0.02);
    EXPECT_LT(c.shiftLow, c.shift);
    EXPECT_GT(c.shiftHigh, c.shift);
}

TEST(GateTimingDecision, ASpeedUpIsDifferentButNotSlower) {
    const TimingComparison c =
        compareTiming(sample(12, 100.0, 0.01, 3), sample(12, 90.0, 0.01, 4), {0.01, 0.03});
    EXPECT_EQ(c.verdict, TimingVerdict::Different);
    EXPECT_FALSE(c.slower());
    EXPECT_LT(c.shift, 0);
}

TEST(GateTimingDecision, ASignificantShiftBelowTheThresholdIsNotDifferent) {
    // 1% apart with 0.1% noise: p is tiny, but 1% is below the 3% that matters.
    const TimingComparison c =
        compareTiming(sample(15, 100.0, 0.001, 5), sample(15, 101.0, 0.001, 6), {0.01, 0.03});
    EXPECT_LE(c.p, 0.01);
    EXPECT_EQ(c.verdict, TimingVerdict::Same);
}

TEST(GateTimingDecision, EqualDistributionsWithEnoughRoundsAreSame) {
    const TimingComparison c =
        compareTiming(sample(30, 100.0, 0.01, 7), sample(30, 100.0, 0.01, 8), {0.01, 0.03});
    EXPECT_EQ(c.verdict, TimingVerdict::Same);
    EXPECT_GT(c.p, 0.01);
}

TEST(GateTimingDecision, NoisyFewRoundsAreUnknownUntilMoreRoundsDecide) {
    const TimingComparison few =
        compareTiming(sample(5, 100.0, 0.08, 9), sample(5, 100.0, 0.08, 10), {0.01, 0.03});
    EXPECT_EQ(few.verdict, TimingVerdict::Unknown);
    const TimingComparison many =
        compareTiming(sample(400, 100.0, 0.08, 9), sample(400, 100.0, 0.08, 10), {0.01, 0.03});
    EXPECT_EQ(many.verdict, TimingVerdict::Same);
}

TEST(GateTimingDecision, BadInputIsAnError) {
    EXPECT_THROW(compareTiming({}, {1.0}, {}), pb::Error);
    EXPECT_THROW(compareTiming({1.0, 2.0}, {1.0, 2.0}, {0.0, 0.03}), pb::Error);
    EXPECT_THROW(compareTiming({0.0, 0.0}, {1.0, 2.0}, {}), pb::Error);
}
