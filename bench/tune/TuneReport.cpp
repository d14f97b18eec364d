#include "TuneReport.h"

#include "profile/PlatformProfile.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pb::bench {

namespace {

std::string figures(const TuneCandidate& c) {
    char buf[160];
    if (c.measured && c.m.ok)
        std::snprintf(buf, sizeof buf, "%.2f ms, %.3f MiB, FLIP %.4f", c.m.frameMs, c.memoryMiB,
                      c.m.flip);
    else
        std::snprintf(buf, sizeof buf, "%.3f MiB, not rendered", c.memoryMiB);
    return buf;
}

} // namespace

std::string paretoTable(const TuneResult& r, const TuneOptions& o) {
    std::ostringstream out;
    char line[400];
    out << "Pareto front of " << r.pareto.size() << " out of " << r.variantsMeasured
        << " measured candidate(s) (frame ms: " << o.timeSource
        << "; FLIP vs the reference; * = chosen;\n"
        << "  " << profile::kGiMemoryDefinition << "):\n";
    std::snprintf(line, sizeof line, "  %1s %9s %9s %8s %11s %5s  %s\n", "", "frame ms", "GI MiB",
                  "FLIP", "relMSE GI", "fits", "switches vs the base");
    out << line;
    for (int i : r.pareto) {
        const TuneCandidate& c = r.candidates[size_t(i)];
        std::snprintf(line, sizeof line, "  %1s %9.2f %9.3f %8.4f %11.4g %5s  %s\n",
                      i == r.chosen ? "*" : "", c.m.frameMs, c.memoryMiB, c.m.flip,
                      c.m.relativeMseGi, c.fits(o) ? "yes" : "no", c.label.c_str());
        out << line;
    }
    return out.str();
}

nlohmann::json tuneJson(const TuneResult& r, const TuneOptions& o) {
    nlohmann::json cands = nlohmann::json::array();
    for (size_t i = 0; i < r.candidates.size(); ++i) {
        const TuneCandidate& c = r.candidates[i];
        nlohmann::json j{{"label", c.label},
                         {"switches", c.switches.valuesJson()},
                         {"gi_memory_mib", c.memoryMiB},
                         {"measured", c.measured},
                         {"fits", c.fits(o)},
                         {"on_pareto_front",
                          std::find(r.pareto.begin(), r.pareto.end(), int(i)) != r.pareto.end()}};
        if (c.measured) {
            j["ok"] = c.m.ok;
            j["measurements"] = c.measurements;
            if (c.m.ok) {
                j["frame_ms"] = c.m.frameMs;
                j["flip"] = c.m.flip;
                j["relative_mse_gi"] = c.m.relativeMseGi;
            } else {
                j["error"] = c.m.error;
            }
        }
        cands.push_back(j);
    }
    auto labels = [&](const std::vector<int>& ids) {
        nlohmann::json a = nlohmann::json::array();
        for (int i : ids)
            a.push_back(r.candidates[size_t(i)].label);
        return a;
    };
    return {{"method", r.method},
            {"budget", {{"frame_ms", o.budgetMs}, {"gi_memory_mib", o.budgetMiB}}},
            {"combinations", r.combinations},
            {"distinct", r.distinct},
            {"over_memory_budget", r.overMemory},
            {"sessions", r.sessions},
            {"candidates_measured", r.variantsMeasured},
            {"chosen", r.chosen >= 0 ? nlohmann::json(r.candidates[size_t(r.chosen)].label)
                                     : nlohmann::json(nullptr)},
            {"pareto", labels(r.pareto)},
            {"closest", labels(r.closest)},
            {"candidates", cands}};
}

std::string nothingFitsMessage(const TuneResult& r, const TuneOptions& o) {
    std::ostringstream out;
    out << "nothing fits " << o.budgetMs << " ms and " << o.budgetMiB << " MiB (" << r.distinct
        << " configuration(s), " << r.overMemory << " over the memory budget, "
        << r.variantsMeasured << " measurement(s)); closest:";
    for (size_t k = 0; k < r.closest.size(); ++k) {
        const TuneCandidate& c = r.candidates[size_t(r.closest[k])];
        out << (k ? "; " : " ") << c.label << " (" << figures(c) << ")";
    }
    if (r.closest.empty()) out << " none ran";
    return out.str();
}

} // namespace pb::bench
