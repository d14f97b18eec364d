#pragma once
// The gate's verdicts, one row per compared figure (counter, baseline, now, verdict), and the
// exit code they add up to (bench/gate/README.md "Exit codes"). GL-free.
#include "GateRecord.h"
#include "TimingDecision.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::gate {

enum class RowStatus {
    Ok,       // equal (counters) or within tolerance
    Changed,  // an exact counter differs: fails until the baseline is updated on purpose
    New,      // measured now, absent from the baseline: fails likewise
    Missing,  // in the baseline, not measured now: fails likewise
    Worse,    // accuracy or instruction count past its tolerance
    Disagree, // the cost model and the GL pass count different pixels
    Better,   // accuracy or instructions improved past the tolerance (passes; update to keep)
    Slower,   // timing: different and slower
    Faster,   // timing: different and faster (passes)
    Same,     // timing: any change is below the threshold
    Unknown,  // timing: undecided within the round budget (passes, reported)
    Skipped,  // not compared (callgrind baseline of another toolchain, ...)
    Failed,   // a part that must run could not (a shader target's compile, CI's compilers)
};
const char* rowStatusName(RowStatus s); // "ok", "CHANGED", ...
bool failsDeterministic(RowStatus s);   // Changed, New, Missing, Worse, Disagree, Failed

struct GateRow {
    std::string profile; // "" for rows about the whole suite
    std::string group; // probes | counters | accuracy | model-vs-gl | timing | callgrind | shaders
    std::string name, baseline, now;
    RowStatus status = RowStatus::Ok;
    std::string note;
};

struct GateOutcome {
    std::vector<GateRow> rows;
    std::vector<std::string> notes; // one line each: skipped parts, warnings
    bool recording = false;         // --update: the rows show what changes in the baseline
    // Under CI=true a timing row still "unknown" at the end of its budget fails the gate
    // (exit 5): a real slowdown on a noisy runner must not land as "unknown".
    bool undecidedFails = false;
    int deterministicFailures() const;
    int timingFailures() const;
    // The timing rows still unknown ("profile: what"), in table order.
    std::vector<std::string> undecidedRows() const;
    // 0 pass, 3 a counter / accuracy / callgrind / shader / agreement failure, 4 timing
    // regressions, 5 only undecided timing rows with undecidedFails (1 is every error: bad
    // option, unreadable baseline, GL failure, a busy machine with --require-quiet).
    int exitCode() const;
};

inline constexpr int kExitRegression = 3;
inline constexpr int kExitTimingRegression = 4;
inline constexpr int kExitUndecided = 5;

// Probe data identity, every exact counter (grouped for display: gl.<pass>.*, cache.*, ...),
// accuracy within the suite's tolerances, and the GL pass's pixels against the model's.
void compareRecords(const GateRecord& baseline, const GateRecord& now, GateOutcome& out);
// Instruction counts of `now` (measured under `key`) against the baseline's record with the
// same key; a baseline without one gives a skipped row and a note, never a failure.
void compareCallgrind(const GateRecord& baseline, const CallgrindRecord& now, GateOutcome& out);
// One timing row: `what` names the compared quantity, `unit` formats medians ("ms", "x").
GateRow timingRow(const std::string& profile, const std::string& what, const TimingComparison& c,
                  const std::string& unit, int rounds, bool budgetReached);

// The readable table (fixed-width columns, one row per line) and the notes.
std::string gateTable(const GateOutcome& o);
nlohmann::json gateJson(const GateOutcome& o);

} // namespace pb::gate
