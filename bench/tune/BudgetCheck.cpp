#include "BudgetCheck.h"

#include <cstdio>

namespace pb::bench {

std::string overBudgetProblem(double remeasuredMs, double searchMs, double budgetMs) {
    if (remeasuredMs <= budgetMs) return "";
    char text[256];
    std::snprintf(text, sizeof text,
                  "the tuned profile re-measured %.2f ms, over the %g ms budget (the search "
                  "measured %.2f ms; near the edge the device's noise decides)",
                  remeasuredMs, budgetMs, searchMs);
    return text;
}

} // namespace pb::bench
