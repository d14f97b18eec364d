// A gate that decides (issue 41): a timing row still "unknown" at the end of its budgets fails
// with exit 5 under CI=true and is named in the summary; outside CI it passes with that line;
// worse outcomes keep their own codes.
#include "bench/gate/GateOutcome.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

using namespace pb::gate;

GateOutcome undecidedOutcome(bool ci) {
    GateOutcome o;
    o.undecidedFails = ci;
    o.rows.push_back(
        {"handheld", "timing", "frame ratio to reference", "0.88", "0.93", RowStatus::Same, ""});
    o.rows.push_back({"pc-low", "timing", "frame ratio to reference", "0.80", "0.85",
                      RowStatus::Unknown,
                      "+6.4% [-0.6%, +16.6%], p=0.011, 15 rounds (budget reached)"});
    return o;
}

TEST(GateUndecided, UnknownFailsWithExitFiveUnderCiAndIsNamed) {
    const GateOutcome ci = undecidedOutcome(true);
    EXPECT_EQ(ci.exitCode(), kExitUndecided);
    EXPECT_EQ(ci.undecidedRows(), std::vector<std::string>{"pc-low: frame ratio to reference"});
    const std::string table = gateTable(ci);
    EXPECT_NE(table.find("gate: undecided (fails under CI=true, exit 5): pc-low: frame ratio to "
                         "reference - rerun on a quieter machine"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("gate: FAIL"), std::string::npos) << table;
    EXPECT_EQ(gateJson(ci)["exit_code"], 5);
    EXPECT_EQ(gateJson(ci)["undecided"].size(), 1u);

    const GateOutcome local = undecidedOutcome(false);
    EXPECT_EQ(local.exitCode(), 0);
    EXPECT_NE(gateTable(local).find("undecided (passes outside CI)"), std::string::npos);
}

TEST(GateUndecided, WorseOutcomesKeepTheirCodes) {
    GateOutcome o = undecidedOutcome(true);
    o.rows.push_back(
        {"pc-high", "timing", "frame ratio to reference", "0.72", "0.80", RowStatus::Slower, ""});
    EXPECT_EQ(o.exitCode(), kExitTimingRegression);
    o.rows.push_back({"pc-high", "counters", "gl.gi-apply", "1", "2", RowStatus::Changed, ""});
    EXPECT_EQ(o.exitCode(), kExitRegression);
    GateOutcome decided;
    decided.undecidedFails = true;
    decided.rows.push_back(
        {"handheld", "timing", "frame ratio to reference", "0.88", "0.88", RowStatus::Same, ""});
    EXPECT_EQ(decided.exitCode(), 0);
}

} // namespace
} // namespace pb::test
