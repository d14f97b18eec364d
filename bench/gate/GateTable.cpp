// gateTable / gateJson of GateOutcome.h: the people and the machine form of the verdicts.
#include "GateOutcome.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pb::gate {

namespace {

int groupRank(const std::string& g) {
    static const char* order[] = {"probes", "counters",  "model-vs-gl",    "accuracy",
                                  "timing", "callgrind", "gl-invocations", "shaders"};
    for (int i = 0; i < 8; ++i)
        if (g == order[i]) return i;
    return 8;
}

} // namespace

std::string gateTable(const GateOutcome& o) {
    std::vector<GateRow> rows = o.rows; // one block per group, profiles in suite order inside
    std::stable_sort(rows.begin(), rows.end(), [](const GateRow& a, const GateRow& b) {
        return groupRank(a.group) < groupRank(b.group);
    });
    std::ostringstream out;
    char line[640];
    const char* fmt = "%-13s %-52s %-32s %-32s %-9s %s\n";
    std::snprintf(line, sizeof line, fmt, "profile", "counter", "baseline", "now", "verdict",
                  "note");
    out << line;
    std::string group;
    for (const GateRow& r : rows) {
        if (r.group != group) {
            group = r.group;
            out << "-- " << group;
            if (group == "counters")
                out << " (exact; gl.<pass> = draws/programs/texture binds/unbinds/clears/"
                       "framebuffer binds of the real frame)";
            else if (group == "accuracy")
                out << " (against the reference profile, tolerances from the baseline)";
            else if (group == "model-vs-gl")
                out << " (GI pixels evaluated: cost model vs the GL pass's own count)";
            else if (group == "shaders")
                out << " (exact; per target and pass, its heaviest fragment program as the "
                       "target's compiler reports it; the note names the figures)";
            out << "\n";
        }
        std::snprintf(line, sizeof line, fmt, r.profile.c_str(), r.name.c_str(), r.baseline.c_str(),
                      r.now.c_str(), rowStatusName(r.status), r.note.c_str());
        out << line;
    }
    for (const std::string& n : o.notes)
        out << "note: " << n << "\n";
    const int d = o.deterministicFailures(), t = o.timingFailures();
    const std::vector<std::string> undecided = o.undecidedRows();
    if (!o.recording && !undecided.empty()) {
        std::string list;
        for (const std::string& u : undecided)
            list += (list.empty() ? "" : "; ") + u;
        out << "gate: undecided (" << (o.undecidedFails ? "fails under CI=true, exit 5" : "passes outside CI")
            << "): " << list << " - rerun on a quieter machine\n";
    }
    if (o.recording)
        out << "gate: --update: " << o.rows.size() << " rows recorded, " << d
            << " of them new or different from the previous baseline\n";
    else
        out << "gate: " << (o.exitCode() == 0 ? "PASS" : "FAIL") << " - " << o.rows.size()
            << " rows, " << d << " counter/accuracy/instruction/shader failure(s), " << t
            << " timing regression(s), " << undecided.size() << " undecided\n";
    return out.str();
}

nlohmann::json gateJson(const GateOutcome& o) {
    nlohmann::json rows = nlohmann::json::array();
    for (const GateRow& r : o.rows)
        rows.push_back({{"profile", r.profile},
                        {"group", r.group},
                        {"name", r.name},
                        {"baseline", r.baseline},
                        {"now", r.now},
                        {"verdict", rowStatusName(r.status)},
                        {"fails", failsDeterministic(r.status) || r.status == RowStatus::Slower},
                        {"note", r.note}});
    return {{"schema", "probebench.gate-result/1"},
            {"pass", o.exitCode() == 0},
            {"exit_code", o.exitCode()},
            {"deterministic_failures", o.deterministicFailures()},
            {"timing_regressions", o.timingFailures()},
            {"undecided", o.undecidedRows()},
            {"rows", rows},
            {"notes", o.notes}};
}

} // namespace pb::gate
