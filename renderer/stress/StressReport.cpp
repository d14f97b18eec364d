#include "stress/StressReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace pb::stress {

namespace {

nlohmann::json variantJson(const StressVariant& v) {
    nlohmann::json settings = nlohmann::json::object();
    for (const std::string& k : v.keys())
        settings[k] = v.get(k);
    return {{"name", v.name}, {"settings", settings}};
}

// NaN/Inf cannot be JSON numbers; an error run has no error figures.
nlohmann::json jsonNumber(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nullptr;
}

std::string runLabel(const StressRun& r) {
    return r.variant + (r.guardsOff ? "/off" : "");
}

std::string cell(const StressRun& r) {
    char buf[32];
    if (r.symptom == "error") return "ERROR";
    if (r.symptom == "nan/inf") {
        std::snprintf(buf, sizeof buf, "NAN %lld", static_cast<long long>(r.m.nonfinitePixels));
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%s %.2g", r.symptom == "wrong" ? "BAD" : "ok", r.m.medianRel);
    return buf;
}

std::string joined(const std::vector<std::string>& v, const char* sep = ", ") {
    std::string out;
    for (const std::string& s : v)
        out += (out.empty() ? "" : sep) + s;
    return out;
}

} // namespace

nlohmann::json sweepJson(const SweepResult& r) {
    nlohmann::json j;
    j["command"] = "stress";
    j["thresholds"] = {{"median_rel", r.options.thresholds.medianRel}};
    j["reference"] = variantJson(r.reference);
    j["variants"] = nlohmann::json::array();
    for (const StressVariant& v : r.options.variants)
        j["variants"].push_back(variantJson(v));
    j["cases"] = nlohmann::json::array();
    int frames = 0;
    for (const CaseSummary& c : r.cases) {
        frames += c.frames;
        j["cases"].push_back(
            {{"name", c.name},
             {"group", c.group},
             {"stresses", c.stresses},
             {"width", c.width},
             {"height", c.height},
             {"truth", c.truth},
             {"frames", c.frames},
             {"reference_nonfinite_pixels", c.reference.nonfinitePixels},
             {"reference_error", c.reference.error.empty() ? nlohmann::json(nullptr)
                                                           : nlohmann::json(c.reference.error)}});
    }
    j["runs"] = nlohmann::json::array();
    int broken = 0, brokenGuarded = 0;
    std::int64_t nonfiniteGuarded = 0;
    for (const StressRun& run : r.runs) {
        const bool bad = run.symptom != "ok";
        broken += bad ? 1 : 0;
        if (!run.guardsOff) {
            brokenGuarded += bad ? 1 : 0;
            nonfiniteGuarded += run.m.nonfinitePixels;
        }
        j["runs"].push_back(
            {{"case", run.caseName},
             {"variant", run.variant},
             {"guards", run.guardsOff ? "off" : "as_given"},
             {"symptom", run.symptom},
             {"nonfinite_pixels", run.m.nonfinitePixels},
             {"nonfinite_gi_texels", run.m.nonfiniteGiTexels},
             {"max_rel", jsonNumber(run.m.maxRel)},
             {"mean_rel", jsonNumber(run.m.meanRel)},
             {"median_rel", jsonNumber(run.m.medianRel)},
             {"error", run.m.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.m.error)},
             {"culprits", run.culprits},
             {"fixed_by", run.fixedBy},
             {"finite_with", run.finiteWith}});
    }
    j["summary"] = {{"runs", r.runs.size()},
                    {"broken", broken},
                    {"broken_with_guards", brokenGuarded},
                    {"nonfinite_with_guards", nonfiniteGuarded},
                    {"frames", frames}};
    return j;
}

std::string sweepText(const SweepResult& r) {
    std::vector<std::string> columns;
    for (const StressRun& run : r.runs)
        if (std::find(columns.begin(), columns.end(), runLabel(run)) == columns.end())
            columns.push_back(runLabel(run));
    std::size_t first = 4;
    for (const CaseSummary& c : r.cases)
        first = std::max(first, c.name.size());
    std::size_t width = 9;
    for (const std::string& c : columns)
        width = std::max(width, c.size());

    std::ostringstream out;
    char buf[64];
    out << "symptom and median relative error of the radiance vs the reference (fp32, rgba32f "
           "target, full resolution, rgba32f probes, guards on); NAN n = n pixels NaN/Inf, BAD = "
           "median error above "
        << r.options.thresholds.medianRel << "; /off = every gi.guard_* off\n\n";
    std::snprintf(buf, sizeof buf, "%-*s", int(first), "case");
    out << buf;
    for (const std::string& c : columns) {
        std::snprintf(buf, sizeof buf, "  %-*s", int(width), c.c_str());
        out << buf;
    }
    out << "\n";
    for (const CaseSummary& c : r.cases) {
        std::snprintf(buf, sizeof buf, "%-*s", int(first), c.name.c_str());
        out << buf;
        for (const std::string& col : columns) {
            std::string text = "-";
            for (const StressRun& run : r.runs)
                if (run.caseName == c.name && runLabel(run) == col) text = cell(run);
            std::snprintf(buf, sizeof buf, "  %-*s", int(width), text.c_str());
            out << buf;
        }
        if (c.reference.nonfinitePixels || !c.reference.error.empty())
            out << "  (reference: " << (c.reference.error.empty() ? "NaN/Inf" : c.reference.error)
                << ")";
        out << "\n";
    }
    out << "\nbroken runs: case, variant, symptom -> culprit; fixed by\n";
    int n = 0;
    for (const StressRun& run : r.runs) {
        if (run.symptom == "ok") continue;
        ++n;
        out << "  " << run.caseName << "  " << runLabel(run) << "  " << run.symptom;
        if (run.symptom == "nan/inf") out << " (" << run.m.nonfinitePixels << " px)";
        if (run.symptom == "wrong") {
            std::snprintf(buf, sizeof buf, " (median %.3g, max %.3g)", run.m.medianRel,
                          run.m.maxRel);
            out << buf;
        }
        if (run.symptom == "error") out << ": " << run.m.error;
        if (!run.culprits.empty()) out << " -> " << joined(run.culprits);
        if (!run.fixedBy.empty())
            out << "; fixed by " << joined(run.fixedBy);
        else if (run.guardsOff)
            out << "; no guard fixes it";
        if (!run.finiteWith.empty() && run.fixedBy.empty())
            out << " (no NaN/Inf with " << joined(run.finiteWith) << ")";
        out << "\n";
    }
    if (n == 0) out << "  none\n";
    return out.str();
}

} // namespace pb::stress
