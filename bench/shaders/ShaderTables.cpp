#include "ShaderTables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace pb::shaders {
namespace {

bool differs(const ProgramStatistics* a, const ProgramStatistics* b) {
    if (!a || !b) return a != b;
    return a->key() != b->key();
}

std::string cell(const std::string& s) {
    return s.empty() ? "-" : s;
}

std::string occupancyName(const TargetStatistics& t) {
    return t.driver == "freedreno" ? "waves" : "threads";
}

} // namespace

std::vector<PassRow> passRows(const TargetStatistics& t) {
    std::vector<PassRow> out;
    for (const VariantStatistics& v : t.variants) {
        if (v.role != "profile" && v.role != "reference") continue;
        if (!v.notRun.empty()) continue;
        for (const std::string& pass : t.passes(v)) {
            const ProgramStatistics* p = t.heaviestFragment(v, pass);
            if (!p) continue;
            out.push_back({v.profile, v.id, pass, p, p->stage("fragment")});
        }
    }
    return out;
}

std::vector<SwitchRow> switchRows(const ShaderStatisticsRun& run, const TargetStatistics& t) {
    std::vector<SwitchRow> out;
    for (const SwitchPair& pair : run.pairs) {
        const VariantStatistics* off = t.variant(pair.offVariant);
        const VariantStatistics* on = t.variant(pair.onVariant);
        if (!off || !on || !off->notRun.empty() || !on->notRun.empty()) continue;
        std::vector<std::string> passes = t.passes(*off);
        for (const std::string& p : t.passes(*on))
            if (std::find(passes.begin(), passes.end(), p) == passes.end()) passes.push_back(p);
        bool any = false;
        for (const std::string& pass : passes) {
            const ProgramStatistics* a = t.heaviestFragment(*off, pass);
            const ProgramStatistics* b = t.heaviestFragment(*on, pass);
            if (!differs(a, b)) continue;
            any = true;
            out.push_back({&pair, pass, a, b, a ? a->stage("fragment") : nullptr,
                           b ? b->stage("fragment") : nullptr});
        }
        if (!any) out.push_back({&pair, "", nullptr, nullptr, nullptr, nullptr});
    }
    return out;
}

std::string figure(double value, bool fractional) {
    if (value < 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, fractional ? "%.2f" : "%.0f", value);
    return buf;
}

std::string change(double off, double on, bool fractional) {
    if (off < 0 || on < 0) return "-";
    const double d = on - off;
    if (std::fabs(d) < (fractional ? 0.005 : 0.5)) return "0";
    char buf[32];
    std::snprintf(buf, sizeof buf, fractional ? "%+.2f" : "%+.0f", d);
    return buf;
}

std::string spillsFills(const StageStatistics* s) {
    if (s && s->has("local")) return figure(s->field("local"), false) + " B local"; // nouveau
    if (!s || s->spills() < 0) return "-";
    return figure(s->spills(), false) + ":" + figure(s->fills(), false);
}

std::string registers(const StageStatistics* s) {
    if (!s) return "-";
    if (s->has("full"))
        return figure(s->field("full"), false) + " full / " + figure(s->field("half"), false) +
               " half";
    if (s->has("max-temps")) return figure(s->field("max-temps"), false) + " temps";
    if (s->has("registers")) return figure(s->field("registers"), false) + " regs";
    if (s->has("gpr")) return figure(s->field("gpr"), false) + " gpr";
    return "-";
}

std::string shaderMarkdown(const ShaderStatisticsRun& run, int level) {
    std::ostringstream md;
    const std::string title(size_t(std::max(level, 1)), '#');
    md << title << " Shader statistics of the weak GPUs' compilers\n\n"
       << "Mesa " << run.mesaVersion << " (drm-shim, no hardware), scene " << run.scene
       << ", probes " << run.probes << ", camera " << run.camera << ". Figures are each compiler's own static estimates for "
       << "one fragment: deterministic for this Mesa version, comparable within one driver, "
          "not timings. A pass's figure is its heaviest fragment program; a loop's body is counted "
          "once (the loops column says how many a program has).\n";
    for (const TargetStatistics& t : run.targets) {
        md << "\n" << title << "# " << t.target << ": " << t.device << " (" << t.driver << ")\n\n";
        if (!t.error.empty()) {
            md << "**Not run:** " << t.error << "\n";
            continue;
        }
        md << t.glVersion << "; " << t.glRenderer << "; " << t.glslVersion << ".\n";
        if (!t.note.empty()) md << "Note: " << t.note << ".\n";
        bool listed = false;
        for (const VariantStatistics& v : t.variants)
            if (!v.notRun.empty()) {
                md << (listed ? "" : "\n") << "- cannot run " << v.id << ": " << v.notRun << "\n";
                listed = true;
            }
        md << "\n| profile | pass | fragment program | inst | cycles | bound | registers | "
           << occupancyName(t) << " | spills:fills | loops |\n"
           << "|---|---|---|---|---|---|---|---|---|---|\n";
        for (const PassRow& r : passRows(t)) {
            const StageStatistics* f = r.fragment;
            md << "| " << r.profile << " | " << r.pass << " | " << r.program->fragment << " | "
               << figure(f->instructions(), false) << " | " << figure(f->cycles(), true) << " | "
               << cell(f->boundUnit()) << " | " << registers(f) << " | "
               << figure(f->occupancy(), false) << " | " << spillsFills(f) << " | "
               << figure(f->field("loops"), false) << " |\n";
        }
        const std::vector<SwitchRow> rows = switchRows(run, t);
        if (rows.empty()) continue;
        md << "\nPer switch, on minus off (the pass's heaviest fragment program):\n\n"
           << "| where | switch | off -> on | pass | inst | cycles | registers (off -> on) | "
           << occupancyName(t) << " | spills:fills (off -> on) |\n"
           << "|---|---|---|---|---|---|---|---|---|\n";
        for (const SwitchRow& r : rows) {
            const SwitchPair& p = *r.pair;
            const std::string where = p.kind == "on_reference" ? "on reference" : "in " + p.profile;
            md << "| " << where << " | " << p.switchKey << " | " << p.offValue << " -> "
               << p.onValue << " | ";
            if (r.pass.empty()) {
                md << "(no program changes) | 0 | 0 | - | - | - |\n";
                continue;
            }
            const StageStatistics *a = r.offFragment, *b = r.onFragment;
            const auto val = [](const StageStatistics* s, double (StageStatistics::*f)() const) {
                return s ? (s->*f)() : -1.0;
            };
            md << r.pass << " | "
               << (a && b ? change(a->instructions(), b->instructions(), false)
                          : (a ? "removed" : "added"))
               << " | "
               << change(val(a, &StageStatistics::cycles), val(b, &StageStatistics::cycles), true)
               << " | " << registers(a) << " -> " << registers(b) << " | "
               << figure(val(a, &StageStatistics::occupancy), false) << " -> "
               << figure(val(b, &StageStatistics::occupancy), false) << " | " << spillsFills(a)
               << " -> " << spillsFills(b) << " |\n";
        }
    }
    return md.str();
}

} // namespace pb::shaders
