#include "GateEnvironment.h"

namespace pb::gate {

namespace {

void probeDataRow(const GateRecord& baseline, const GateRecord& now, GateOutcome& out) {
    GateRow row{"", "probes", "probe data", baseline.probes, now.probes, RowStatus::Ok, ""};
    if (baseline.probes != now.probes) {
        row.status = RowStatus::Changed;
        row.note = "not the probe data the baseline was recorded with: re-record both "
                   "together (--update)";
    }
    out.rows.push_back(row);
}

void bakeRow(const GateRecord& baseline, const GateRecord& now, GateOutcome& out) {
    const GateEnvironment& b = baseline.environment;
    const GateEnvironment& n = now.environment;
    GateRow row{"", "probes", "bake on this machine", baseline.bake.empty() ? "-" : baseline.bake,
                now.bake, RowStatus::Ok, ""};
    if (baseline.bake.empty()) {
        row.status = RowStatus::Skipped;
        row.note = "the baseline records no bake of its own (an older file; --update)";
    } else if (baseline.bake != now.bake) {
        const bool otherCpu = b.cpu.empty() || b.cpu != n.cpu;
        const bool otherIsa = b.embreeIsa != n.embreeIsa;
        if (otherCpu || otherIsa) {
            row.status = RowStatus::Skipped;
            row.note = "differs on another machine; the counters use the committed probe file";
            out.notes.push_back(
                "environment: this machine's bake differs from the recording machine's (" +
                (otherCpu ? "CPU '" + n.cpu + "', the baseline's '" + b.cpu + "'"
                          : "Embree " + n.embreeIsa + ", the baseline's " + b.embreeIsa) +
                "): expected in the last bits across CPUs; every figure is measured with the "
                "committed probe file, so nothing else depends on it");
        } else {
            row.status = RowStatus::Changed;
            row.note = "the bake changed on the recording machine's CPU: re-record on purpose";
        }
    }
    out.rows.push_back(row);
}

} // namespace

bool otherMachine(const GateRecord& baseline, const GateRecord& now) {
    const GateEnvironment& b = baseline.environment;
    const GateEnvironment& n = now.environment;
    if (b.cpu.empty() || b.embreeIsa.empty()) return false; // an older baseline: strict
    return b.cpu != n.cpu || b.embreeIsa != n.embreeIsa;
}

void compareEnvironment(const GateRecord& baseline, const GateRecord& now, GateOutcome& out) {
    const bool hasBaseline = !baseline.probes.empty(); // not a new suite's --update
    const GateEnvironment& b = baseline.environment;
    const GateEnvironment& n = now.environment;
    std::string baseGl = b.glRenderer;
    if (baseGl.empty() && baseline.recorded.contains("gl_renderer") &&
        baseline.recorded.at("gl_renderer").is_string())
        baseGl = baseline.recorded.at("gl_renderer").get<std::string>();
    if (hasBaseline && !baseGl.empty() && baseGl != n.glRenderer)
        out.notes.push_back("environment: GL '" + n.glRenderer + "', the baseline's '" + baseGl +
                            "': GL call counts stay exact; the GL pass's pixels and the accuracy "
                            "are compared within their tolerances, as always");
    probeDataRow(baseline, now, out);
    if (hasBaseline) bakeRow(baseline, now, out);
}

} // namespace pb::gate
