#include "GateTiming.h"

#include "bench/report/GiSections.h"
#include "core/Error.h"
#include "metrics/Statistics.h"

namespace pb::gate {

double giSectionsMs(const std::vector<std::pair<std::string, double>>& sections) {
    double g = 0;
    for (const auto& [name, ms] : sections)
        if (bench::isGiSection(name)) g += ms;
    return g;
}

RoundTimes timeRound(GateRenderer& r, bench::SectionTimer& timer, int frames) {
    std::vector<double> frame, gi;
    for (int f = 0; f < frames; ++f) {
        bool ok = false;
        for (int attempt = 0; attempt < 3 && !ok; ++attempt) {
            timer.beginFrame();
            r.frame(&timer);
            ok = timer.endFrame();
        }
        if (!ok) throw Error("timer queries reported disjoint GPU time 3 times in a row");
        frame.push_back(timer.frameMs());
        gi.push_back(giSectionsMs(timer.sections()));
    }
    return {stats::summarize(frame).median, stats::summarize(gi).median};
}

SequentialTiming
runSequential(const std::vector<std::string>& names,
              const std::function<std::vector<std::pair<double, double>>(int)>& measure,
              const std::vector<std::vector<double>>& fixedBaselines, bool decide,
              const TimingSettings& s, double threshold, int budget,
              const std::function<void(const std::string&)>& progress) {
    SequentialTiming t;
    for (size_t q = 0; q < names.size(); ++q) {
        t.quantities.push_back({names[q], {}, {}, {}});
        if (q < fixedBaselines.size()) t.quantities[q].baseline = fixedBaselines[q];
    }
    auto fixed = [&](size_t q) { return q < fixedBaselines.size() && !fixedBaselines[q].empty(); };
    int target = decide ? std::min(s.minRounds, budget) : budget;
    while (true) {
        for (; t.rounds < target; ++t.rounds) {
            const std::vector<std::pair<double, double>> v = measure(t.rounds);
            for (size_t q = 0; q < t.quantities.size() && q < v.size(); ++q) {
                if (!fixed(q)) t.quantities[q].baseline.push_back(v[q].first);
                t.quantities[q].candidate.push_back(v[q].second);
            }
        }
        if (!decide) return t;
        t.decided = true;
        bool unknown = false;
        std::string line = std::to_string(t.rounds) + " rounds:";
        for (TimedQuantity& q : t.quantities) {
            q.comparison = compareTiming(q.baseline, q.candidate, {s.alpha, threshold});
            unknown = unknown || q.comparison.verdict == TimingVerdict::Unknown;
            line += " " + q.name + " " + timingVerdictName(q.comparison.verdict) + " (" +
                    timingSummary(q.comparison) + ")";
        }
        if (progress) progress(line);
        if (!unknown) return t;
        if (t.rounds >= budget) {
            t.budgetReached = true;
            return t;
        }
        target = std::min(budget, t.rounds + s.roundStep);
    }
}

} // namespace pb::gate
