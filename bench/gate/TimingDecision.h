#pragma once
// The timing gate's decision for two samples measured in one job (bench/gate/README.md), after
// Chromium's Pinpoint: p = min(Mann-Whitney U, Kolmogorov-Smirnov), two-sided.
//   different: p <= alpha AND the shift (Hodges-Lehmann, relative to the baseline's median)
//              exceeds the threshold in size - a real change that matters;
//   same:      the shift's (1 - alpha) confidence interval lies inside +-threshold - any change
//              is smaller than the threshold (Pinpoint reaches this with a p-value ceiling per
//              sample size; the interval says the same thing in the units of the threshold);
//   unknown:   neither yet: measure more rounds, up to the budget.
// Samples are per-round values (each the median of K frames), baseline and candidate rounds
// interleaved in time, or dimensionless ratios. GL-free.
#include <cstddef>
#include <string>
#include <vector>

namespace pb::gate {

enum class TimingVerdict { Same, Different, Unknown };
const char* timingVerdictName(TimingVerdict v); // "same", "different", "unknown"

struct TimingRule {
    double alpha = 0.01;     // significance for "different", and 1 - the interval's level
    double threshold = 0.03; // relative shift that matters (0.03 = 3%)
};

struct TimingComparison {
    TimingVerdict verdict = TimingVerdict::Unknown;
    double pMannWhitney = 1, pKolmogorovSmirnov = 1, p = 1;
    double baselineMedian = 0, candidateMedian = 0;
    // (candidate - baseline) / baseline median: Hodges-Lehmann estimate and its interval.
    double shift = 0, shiftLow = 0, shiftHigh = 0;
    size_t baselineCount = 0, candidateCount = 0;
    bool slower() const { return verdict == TimingVerdict::Different && shift > 0; }
};

// Throws pb::Error for an empty sample, a non-finite value or a non-positive baseline median.
TimingComparison compareTiming(const std::vector<double>& baseline,
                               const std::vector<double>& candidate, const TimingRule& rule);

// "+2.9% [+1.8%, +4.0%], p=0.0004" for tables.
std::string timingSummary(const TimingComparison& c);

} // namespace pb::gate
