#pragma once
// What the report says about how far its timings can be trusted: whether the machine was quiet
// while each session was timed (core/MachineState.h), and whether a profile's frame budget can
// be judged at all - only on the device the budget is for ([budget] device), never on another.
#include "BenchResult.h"

#include <string>

namespace pb::bench {

// "" when every session was timed on a quiet machine; else one line naming the figures of
// each noisy session, for the report's and the summary's opening warning.
std::string machineWarning(const BenchResult& r);

// Whether the frame budget of `p` is judged here: its [budget] device names this timing
// device (a case-insensitive part of `glRenderer`).
bool budgetJudged(const profile::PlatformProfile& p, const std::string& glRenderer);

// "budget of Tegra X1" / "budget of the target device": what a plain budget cell says.
std::string budgetOwnerText(const profile::PlatformProfile& p);

// What switching to this variant costs on top of a steady frame: the median of its switch
// frames (the first frame of each round, never in the statistics) minus its steady median.
// NaN when not measured; "n/a" or "+1.23" as text.
double switchCostMs(const VariantResult& v);
std::string switchCostText(const VariantResult& v);

} // namespace pb::bench
