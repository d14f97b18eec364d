#pragma once
// The level the bench's intervals really have, for every header, chart and line that shows one
// (issue 25, item 1): ranks give discrete coverages (the paired deltas: 75% at 3 rounds, 96.9%
// at 6, 95.1% at 10), so "95% CI" was wrong at every round count - and at 1 round there is no
// interval at all. The JSON carries each interval's `ci_level`; these say it in words.
#include "BenchResult.h"

#include <string>
#include <vector>

namespace pb::bench {

// "96.9% CI" when every level is the same, "CI ≥ 75%" when they differ, "no CI" when none has
// any coverage. Rounded down to 0.1%: 94.99% reads 94.9%, never 95%.
std::string ciLabel(const std::vector<double>& levels);

// The levels of the intervals the tables print: each ok variant's frame median, each measured
// delta (vs the reference and the ablation).
std::vector<double> frameCiLevels(const BenchResult& r);
std::vector<double> deltaCiLevels(const BenchResult& r);

// The least coverage of the delta intervals `rounds` interleaved rounds give (the paired
// shift's; the frame medians pool rounds x frames samples and reach more).
double deltaLevelOfRounds(int rounds);
// The fewest rounds whose delta intervals reach 95%.
int roundsFor95();
// "" when `rounds` give 95% intervals; else one sentence saying what they give and what would.
std::string roundsWarning(int rounds);

} // namespace pb::bench
