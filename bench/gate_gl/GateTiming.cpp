#include "GateTiming.h"

#include "bench/report/GiSections.h"
#include "core/Error.h"
#include "metrics/Statistics.h"

#include <chrono>

namespace pb::gate {

double giSectionsMs(const std::vector<std::pair<std::string, double>>& sections) {
    double g = 0;
    for (const auto& [name, ms] : sections)
        if (bench::isGiSection(name)) g += ms;
    return g;
}

RoundTimes timeRound(GateRenderer& r, bench::SectionTimer& timer, int frames) {
    // The first frame after the other side's is a switch frame (the bench's likewise): never
    // timed, so a round's value is the steady state's.
    r.frame(nullptr);
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
              const TimingSettings& s, double threshold, int budget, double timeBudgetSeconds,
              const std::function<void(const std::string&)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
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
        // The round budget, then the time budget for a verdict still unknown; a hard cap keeps
        // a pathologically fast frame from running thousands of rounds.
        const bool roundsLeft = t.rounds < budget;
        const bool timeLeft = elapsed() < timeBudgetSeconds && t.rounds < kMaxRounds;
        if (!roundsLeft && !timeLeft) {
            t.budgetReached = true;
            return t;
        }
        target = roundsLeft ? std::min(budget, t.rounds + s.roundStep) : t.rounds + s.roundStep;
        if (!roundsLeft && progress)
            progress("still unknown after the round budget: more rounds within the time budget (" +
                     std::to_string(int(timeBudgetSeconds - elapsed())) + " s left)");
    }
}

} // namespace pb::gate
