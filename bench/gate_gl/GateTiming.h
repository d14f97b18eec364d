#pragma once
// The gate's timing: rounds of K frames (the round's value is their median), baseline and
// candidate interleaved in one job with the order alternating per round (A B, B A, A B, ...),
// decided after each step of rounds by bench/gate/TimingDecision.h until the verdict is known
// or the round budget is spent. Two uses (bench/gate/README.md "Timing"):
//   ratio:   in one process, a profile's frame over the reference's in the same round,
//            compared with the ratios stored in the baseline (never with absolute times);
//   against: the same profile in two worker processes - this binary and --against's -
//            compared round by round (GateWorker.h).
#include "GateMeasure.h"
#include "bench/gate/GateRecord.h"
#include "bench/gate/TimingDecision.h"
#include "bench/runner/SectionTimer.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace pb::gate {

struct RoundTimes {
    double frameMs = 0; // median over the round's frames
    double giMs = 0;    // the GI sections (bench/report/GiSections.h) of the same frames, median
};

// The GI share of one frame's sections: those bench::isGiSection names (the bench's "GI ms",
// upsample included), so the gate and the bench call the same passes GI.
double giSectionsMs(const std::vector<std::pair<std::string, double>>& sections);

// K timed frames of one renderer.
RoundTimes timeRound(GateRenderer& r, bench::SectionTimer& timer, int frames);

// One compared quantity (a frame ratio, frame ms, GI ms): its per-round samples and verdict.
struct TimedQuantity {
    std::string name;
    std::vector<double> baseline, candidate; // per round
    TimingComparison comparison;
};

struct SequentialTiming {
    std::vector<TimedQuantity> quantities;
    int rounds = 0;
    bool decided = false;       // comparisons were made (false while recording a baseline)
    bool budgetReached = false; // stopped at the budget with a verdict still unknown
};

// measure(round) -> per quantity {baseline value, candidate value} of one round (the callee
// alternates the order by round parity). A quantity whose `fixedBaselines` entry is non-empty
// is compared with that sample (stored ratios) and measure's first value is ignored. With
// `decide` false: exactly `budget` rounds, no comparison (recording a baseline). Otherwise
// steps of rounds until no quantity is unknown, or the round budget is spent and the timing
// has run `timeBudgetSeconds` (at most kMaxRounds). `progress`: a line per step.
inline constexpr int kMaxRounds = 200;
SequentialTiming
runSequential(const std::vector<std::string>& names,
              const std::function<std::vector<std::pair<double, double>>(int)>& measure,
              const std::vector<std::vector<double>>& fixedBaselines, bool decide,
              const TimingSettings& s, double threshold, int budget, double timeBudgetSeconds,
              const std::function<void(const std::string&)>& progress);

} // namespace pb::gate
