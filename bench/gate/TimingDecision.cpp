#include "TimingDecision.h"

#include "core/Error.h"
#include "metrics/Statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pb::gate {

const char* timingVerdictName(TimingVerdict v) {
    switch (v) {
    case TimingVerdict::Same:
        return "same";
    case TimingVerdict::Different:
        return "different";
    case TimingVerdict::Unknown:
        break;
    }
    return "unknown";
}

TimingComparison compareTiming(const std::vector<double>& baseline,
                               const std::vector<double>& candidate, const TimingRule& rule) {
    if (!(rule.alpha > 0 && rule.alpha < 1) || !(rule.threshold > 0))
        throw Error("timing gate: alpha must be in (0,1) and the threshold positive");
    TimingComparison c;
    c.baselineCount = baseline.size();
    c.candidateCount = candidate.size();
    c.baselineMedian = stats::summarize(baseline).median;
    c.candidateMedian = stats::summarize(candidate).median;
    if (!(c.baselineMedian > 0)) throw Error("timing gate: the baseline's median must be positive");
    c.pMannWhitney = stats::mannWhitneyP(baseline, candidate);
    c.pKolmogorovSmirnov = stats::kolmogorovSmirnovP(baseline, candidate);
    c.p = std::min(c.pMannWhitney, c.pKolmogorovSmirnov);
    const stats::Shift s = stats::hodgesLehmannShift(baseline, candidate, 1.0 - rule.alpha);
    c.shift = s.estimate / c.baselineMedian;
    c.shiftLow = s.ciLow / c.baselineMedian;
    c.shiftHigh = s.ciHigh / c.baselineMedian;
    if (c.p <= rule.alpha && std::abs(c.shift) > rule.threshold)
        c.verdict = TimingVerdict::Different;
    else if (c.shiftLow > -rule.threshold && c.shiftHigh < rule.threshold)
        c.verdict = TimingVerdict::Same;
    else
        c.verdict = TimingVerdict::Unknown;
    return c;
}

std::string timingSummary(const TimingComparison& c) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%+.1f%% [%+.1f%%, %+.1f%%], p=%.2g", 100 * c.shift,
                  100 * c.shiftLow, 100 * c.shiftHigh, c.p);
    return buf;
}

} // namespace pb::gate
