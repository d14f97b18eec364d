#pragma once
// Whether a tuned profile, loaded back from its file and measured again, still holds its
// frame-time budget (issue 25, item 5): tune used to write a profile that re-measured 48.5 ms
// against a 40 ms budget, note it, and exit 0.
#include <string>

namespace pb::bench {

// "" when `remeasuredMs` is within `budgetMs`; otherwise the problem, in words, for the
// one-line error (the search's own figure `searchMs` beside it: near the edge the device's
// noise decides).
std::string overBudgetProblem(double remeasuredMs, double searchMs, double budgetMs);

} // namespace pb::bench
