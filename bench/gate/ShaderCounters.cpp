#include "ShaderCounters.h"

#include "bench/shaders/ShaderTables.h"

#include <algorithm>
#include <cmath>

namespace pb::gate {

Counters shaderStageCounters(const shaders::StageStatistics& f) {
    Counters c;
    // The accessors give -1 for a figure this driver does not report.
    auto add = [&c](const char* name, double value, double scale = 1.0) {
        if (value >= 0) c.emplace_back(name, std::int64_t(std::llround(value * scale)));
    };
    add("instructions", f.instructions());
    add("milli_cycles", f.cycles(), 1000.0);
    add("spills", f.spills());
    add("fills", f.fills());
    add("registers_full", f.fullRegisters());
    add("registers_half", f.halfRegisters());
    add("occupancy", f.occupancy());
    add("loops", f.field("loops"));
    add("local_bytes", f.field("local"));
    return c;
}

ShaderRecord shaderRecordOf(const shaders::ShaderStatisticsRun& run,
                            const std::vector<std::string>& drivers,
                            const std::vector<std::string>& profiles) {
    ShaderRecord r;
    r.key = {run.mesaVersion, drivers};
    for (const shaders::TargetStatistics& t : run.targets) {
        if (!t.error.empty()) continue;
        ShaderTargetRecord tr{t.target, {}};
        // passRows also lists the reference variant at the plan's size ("reference@384x216");
        // a suite profile's own variant is named by the profile.
        for (const shaders::PassRow& row : shaders::passRows(t))
            if (std::find(profiles.begin(), profiles.end(), row.variant) != profiles.end() &&
                !tr.pass(row.variant, row.pass))
                tr.passes.push_back({row.variant, row.pass, shaderStageCounters(*row.fragment)});
        r.targets.push_back(std::move(tr));
    }
    return r;
}

std::string shaderCounterLabel(const std::string& counter) {
    static const std::pair<const char*, const char*> kLabels[] = {
        {"instructions", "inst"},   {"milli_cycles", "mcycles"}, {"registers_full", "full"},
        {"registers_half", "half"}, {"occupancy", "occ"},        {"local_bytes", "local B"},
        {"predicted_ns", "ns"},     {"alu_ns", "alu ns"},        {"texture_ns", "tex ns"},
        {"memory_ns", "mem ns"},    {"rop_ns", "rop ns"}};
    for (const auto& [name, label] : kLabels)
        if (counter == name) return label;
    return counter;
}

} // namespace pb::gate
