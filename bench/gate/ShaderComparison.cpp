#include "ShaderComparison.h"

#include "GateEnvironment.h"

#include "ShaderCounters.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

namespace pb::gate {

namespace {

const char* kShaderGroup = "shaders";

// "inst/mcycles/spills/fills/full/half/occ/loops" of the fields either side has, in the
// order they were measured (then the baseline's own).
std::vector<std::string> shaderFields(const Counters* base, const Counters* now) {
    std::vector<std::string> out;
    for (const Counters* c : {now, base})
        if (c)
            for (const auto& [k, v] : *c)
                if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
    return out;
}

std::string shaderValues(const Counters* c, const std::vector<std::string>& fields) {
    if (!c) return "-";
    std::string s;
    for (const std::string& f : fields) {
        auto it = std::find_if(c->begin(), c->end(), [&](const auto& kv) { return kv.first == f; });
        if (!s.empty()) s += '/';
        s += it == c->end() ? std::string("-") : std::to_string(it->second);
    }
    return s;
}

// "inst 132 -> 142 (+10), fills - -> 3": every figure that moved, old and new.
std::string shaderChanges(const Counters& base, const Counters& now,
                          const std::vector<std::string>& fields) {
    auto find = [](const Counters& c, const std::string& f) -> const std::int64_t* {
        for (const auto& [k, v] : c)
            if (k == f) return &v;
        return nullptr;
    };
    std::string note;
    for (const std::string& f : fields) {
        const std::int64_t *b = find(base, f), *n = find(now, f);
        if (b && n && *b == *n) continue;
        note += (note.empty() ? "" : ", ") + shaderCounterLabel(f) + " " +
                (b ? std::to_string(*b) : "-") + " -> " + (n ? std::to_string(*n) : "-");
        if (b && n)
            note += std::string(" (") + (*n > *b ? "+" : "") + std::to_string(*n - *b) + ")";
    }
    return note;
}

GateRow shaderPassRow(const std::string& target, const ShaderPassRecord* base,
                      const ShaderPassRecord* now) {
    const ShaderPassRecord& any = now ? *now : *base;
    const std::vector<std::string> fields =
        shaderFields(base ? &base->counters : nullptr, now ? &now->counters : nullptr);
    std::string labels;
    for (const std::string& f : fields)
        labels += (labels.empty() ? "" : "/") + shaderCounterLabel(f);
    // The figures' names go to the note (they differ per driver and would not fit the name
    // column); a changed row's note names what moved instead.
    GateRow row{any.profile,
                kShaderGroup,
                target + " " + any.pass,
                shaderValues(base ? &base->counters : nullptr, fields),
                shaderValues(now ? &now->counters : nullptr, fields),
                RowStatus::Ok,
                labels};
    if (!base)
        row.status = RowStatus::New;
    else if (!now)
        row.status = RowStatus::Missing;
    else if (base->counters != now->counters) {
        // Counters are stored sorted by name in the file: compare as maps, not as sequences.
        const std::map<std::string, std::int64_t> b(base->counters.begin(), base->counters.end()),
            n(now->counters.begin(), now->counters.end());
        if (b != n) {
            row.status = RowStatus::Changed;
            row.note = shaderChanges(base->counters, now->counters, fields);
        }
    }
    return row;
}

// The target a shaderRunProblems line names ("mali-g52: ...").
std::string problemTarget(const std::string& line) {
    const size_t colon = line.find(": ");
    return colon == std::string::npos ? line : line.substr(0, colon);
}

} // namespace

// A model row that moved only within the other-machine tolerance (every counter).
static bool modelWithinOtherMachineTolerance(const ShaderPassRecord& base, const ShaderPassRecord& now) {
    if (base.counters.size() != now.counters.size()) return false;
    for (const auto& [k, v] : now.counters) {
        auto it = std::find_if(base.counters.begin(), base.counters.end(),
                               [&](const auto& kv) { return kv.first == k; });
        if (it == base.counters.end()) return false;
        const double b = double(it->second), n = double(v);
        if (std::abs(n - b) > kOtherMachineCacheTolerance * std::max(std::abs(b), 1.0)) return false;
    }
    return true;
}

void compareShaders(const GateRecord& baseline, const ShaderRecord& now,
                    const std::vector<std::string>& problems, GateOutcome& out,
                    bool otherMachine) {
    std::set<std::string> failed;
    for (const std::string& p : problems) {
        failed.insert(problemTarget(p));
        out.rows.push_back(
            {"", kShaderGroup, problemTarget(p), "-", "failed", RowStatus::Failed, p});
    }
    const ShaderRecord* base = baseline.shadersFor(now.key);
    if (!base && !out.recording) {
        std::string have;
        for (const ShaderRecord& s : baseline.shaders)
            have += (have.empty() ? "" : "; ") + s.key.text();
        const std::string why =
            have.empty() ? "no shader baseline (--update records it)"
                         : "skipped: baseline has " + have + ", this machine " + now.key.text();
        out.notes.push_back("shaders: " + why);
        out.rows.push_back({"", kShaderGroup, "compiler statistics", have.empty() ? "-" : have,
                            now.key.text(), RowStatus::Skipped, why});
        return;
    }
    const ShaderRecord none;
    const ShaderRecord& b = base ? *base : none;
    for (const ShaderTargetRecord& t : now.targets) {
        if (failed.count(t.target)) continue;
        const ShaderTargetRecord* bt = b.target(t.target);
        for (const ShaderPassRecord& p : t.passes) {
            const ShaderPassRecord* bp = bt ? bt->pass(p.profile, p.pass) : nullptr;
            GateRow row = shaderPassRow(t.target, bp, &p);
            if (row.status == RowStatus::Changed && otherMachine && bp &&
                t.target.rfind("model:", 0) == 0 && modelWithinOtherMachineTolerance(*bp, p)) {
                row.status = RowStatus::Ok;
                row.note += " (within 0.05% on another machine)";
            }
            out.rows.push_back(row);
        }
        if (bt)
            for (const ShaderPassRecord& p : bt->passes)
                if (!t.pass(p.profile, p.pass))
                    out.rows.push_back(shaderPassRow(t.target, &p, nullptr));
    }
    for (const ShaderTargetRecord& bt : b.targets)
        if (!now.target(bt.target) && !failed.count(bt.target))
            out.rows.push_back({"", kShaderGroup, bt.target, "recorded", "-", RowStatus::Missing,
                                "in the baseline, not measured now (suite.shader_targets)"});
}

void shadersNotBuilt(const GateRecord& baseline, const std::string& why, bool onCi,
                     GateOutcome& out) {
    const std::string hint = why.find("scripts/mesa-shim.sh") == std::string::npos
                                 ? "; scripts/mesa-shim.sh builds them"
                                 : "";
    if (onCi && !baseline.shaders.empty()) {
        std::string have;
        for (const ShaderRecord& s : baseline.shaders)
            have += (have.empty() ? "" : "; ") + s.key.text();
        out.rows.push_back({"", kShaderGroup, "compiler statistics", have, "not built",
                            RowStatus::Failed,
                            "CI=true and the baseline has shader statistics: " + why + hint});
        return;
    }
    out.notes.push_back("shaders: not measured - " + why + hint);
}

bool runningOnCi() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

} // namespace pb::gate
