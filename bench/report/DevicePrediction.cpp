#include "DevicePrediction.h"

#include "Html.h"

#include <cstdio>
#include <sstream>

namespace pb::bench {
namespace predtables {

const char* kPredictionIntro =
    "Predicted by the device model (bench/devicemodel/README.md): per pass the largest of its "
    "ALU, texture, memory and ROP demands - counted exactly by the testbed, the ALU from the "
    "device's stand-in compiler - over the device file's rates, plus a fixed cost per draw. Not "
    "a measurement; deterministic on any machine. \"measured\" is this machine's timing.";

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

std::string ms(double v, int decimals = 3) {
    if (!std::isfinite(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string signedMs(double v) {
    if (!std::isfinite(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.3f", v);
    return buf;
}

// Whether the model and this machine agree on the direction of a switch (within 1% of the
// frame either side counts as "no change").
std::string agreement(const PredictedDelta& d, double predictedFrame, double measuredFrame) {
    if (!std::isfinite(d.ms) || !std::isfinite(d.measuredMs)) return "-";
    auto sign = [](double delta, double frame) {
        return std::abs(delta) <= 0.01 * frame ? 0 : (delta < 0 ? -1 : 1);
    };
    const int p = sign(d.ms, predictedFrame), m = sign(d.measuredMs, measuredFrame);
    return p == m ? "same" : "opposite";
}

std::string switchText(const PredictedDelta& d) {
    if (d.kind == "vs_reference") return "profile vs reference";
    return (d.kind == "in_profile" ? "-" : "+") + d.switchKey + " (" +
           (d.kind == "in_profile" ? d.onValue + " -> " + d.offValue : d.offValue + " -> " + d.onValue) +
           ")";
}

// The delta as the table states it: in_profile rows say what reverting the switch does.
double shown(const PredictedDelta& d, double v) { return d.kind == "in_profile" ? -v : v; }

// "33.3 ms: 20.74 at 1280x720, ok" - the profile's budget against its own-size frame.
std::string budgetText(const PredictedSession& s, bool markdown) {
    if (!s.ownDevice) return "-";
    std::string t = "budget " + ms(s.budgetMs, 1) + " ms: ";
    if (!std::isfinite(s.ownSizeMs)) return t + "not predicted";
    t += ms(s.ownSizeMs, 2) + " at " + std::to_string(s.ownWidth) + "x" + std::to_string(s.ownHeight);
    if (s.overBudget()) return t + (markdown ? ", **over**" : ", over");
    return t + ", ok";
}

std::string boundPasses(const PredictedVariant& v) {
    std::string out;
    for (const PredictedPass& p : v.passes)
        if (p.ms > 0) out += (out.empty() ? "" : ", ") + p.pass + " " + p.bound;
    return out;
}

} // namespace predtables
using namespace predtables;

nlohmann::json predictionsJson(const std::vector<DevicePrediction>& devices) {
    nlohmann::json out = nlohmann::json::array();
    for (const DevicePrediction& d : devices) {
        nlohmann::json sessions = nlohmann::json::array();
        for (const PredictedSession& s : d.sessions) {
            nlohmann::json variants = nlohmann::json::array();
            for (const PredictedVariant& v : s.variants) {
                nlohmann::json passes = nlohmann::json::array();
                for (const PredictedPass& p : v.passes) {
                    nlohmann::json j = p.detail;
                    j["measured_ms"] = number(p.measuredMs);
                    passes.push_back(j);
                }
                nlohmann::json vj = {{"variant", v.id},       {"label", v.label},
                                     {"role", v.role},        {"predicted_ms", number(v.ms)},
                                     {"measured_ms", number(v.measuredMs)},
                                     {"passes", passes}};
                if (!v.error.empty()) vj["not_predicted"] = v.error;
                variants.push_back(vj);
            }
            nlohmann::json deltas = nlohmann::json::array();
            for (const PredictedDelta& x : s.deltas)
                deltas.push_back({{"kind", x.kind},
                                  {"switch", x.switchKey},
                                  {"off", x.offValue},
                                  {"on", x.onValue},
                                  {"off_variant", x.offVariant},
                                  {"on_variant", x.onVariant},
                                  {"predicted_delta_ms", number(x.ms)},
                                  {"measured_delta_ms", number(x.measuredMs)}});
            sessions.push_back({{"profile", s.profile},
                                {"width", s.width},
                                {"height", s.height},
                                {"own_device", s.ownDevice},
                                {"budget_ms", s.ownDevice ? nlohmann::json(s.budgetMs) : nlohmann::json()},
                                {"own_size", s.ownDevice ? nlohmann::json{s.ownWidth, s.ownHeight} : nlohmann::json()},
                                {"predicted_own_size_ms", number(s.ownSizeMs)},
                                {"predicted_over_budget", s.overBudget()},
                                {"variants", variants},
                                {"deltas", deltas}});
        }
        nlohmann::json j = {{"model", "model: " + d.device},
                            {"device", d.device},
                            {"label", d.label},
                            {"compiler", d.compiler},
                            {"mesa_version", d.mesaVersion},
                            {"spec", d.spec},
                            {"sessions", sessions}};
        if (!d.error.empty()) j["error"] = d.error;
        out.push_back(j);
    }
    return out;
}

std::string predictionsMarkdown(const std::vector<DevicePrediction>& devices) {
    if (devices.empty()) return "";
    std::ostringstream out;
    out << "\nDevice model: " << kPredictionIntro << "\n";
    for (const DevicePrediction& d : devices) {
        out << "\n### model: " << d.device << " (" << d.label << "; compiler " << d.compiler << ")\n\n";
        if (!d.error.empty()) {
            out << "**Not predicted:** " << d.error << "\n";
            continue;
        }
        out << "| profile | size | predicted ms (model: " << d.device
            << ") | budget | passes: bound unit | measured ms (this machine) |\n|---|---|---|---|---|---|\n";
        for (const PredictedSession& s : d.sessions) {
            const PredictedVariant& v = s.variants.at(0);
            out << "| " << s.profile << " | " << s.width << "x" << s.height << " | "
                << (v.error.empty() ? ms(v.ms) : "not predicted: " + v.error) << " | "
                << budgetText(s, true)
                << " | " << boundPasses(v) << " | " << ms(v.measuredMs) << " |\n";
        }
        out << "\n| profile | pass | predicted ms (model: " << d.device
            << ") | bound | ALU / texture / memory / ROP ms | measured ms (this machine) |\n|---|---|---|---|---|---|\n";
        for (const PredictedSession& s : d.sessions)
            for (const PredictedPass& p : s.variants.at(0).passes) {
                const nlohmann::json u = p.detail.is_object() && p.detail.contains("predicted_unit_ms")
                                             ? p.detail["predicted_unit_ms"]
                                             : nlohmann::json::object();
                out << "| " << s.profile << " | " << p.pass << " | " << ms(p.ms) << " | " << p.bound
                    << " | " << ms(u.value("alu", 0.0)) << " / " << ms(u.value("texture", 0.0)) << " / "
                    << ms(u.value("memory", 0.0)) << " / " << ms(u.value("rop", 0.0)) << " | "
                    << ms(p.measuredMs) << " |\n";
            }
        bool header = false;
        for (const PredictedSession& s : d.sessions) {
            const double pf = s.variants.at(0).ms, mf = s.variants.at(0).measuredMs;
            for (const PredictedDelta& x : s.deltas) {
                if (!header) {
                    out << "\n| profile | switch | predicted Δms (model: " << d.device
                        << ") | measured Δms (this machine) | direction |\n|---|---|---|---|---|\n";
                    header = true;
                }
                out << "| " << s.profile << " | " << switchText(x) << " | " << signedMs(shown(x, x.ms))
                    << " | " << signedMs(shown(x, x.measuredMs)) << " | " << agreement(x, pf, mf) << " |\n";
            }
        }
    }
    return out.str();
}

std::string predictionsHtml(const std::vector<DevicePrediction>& devices) {
    if (devices.empty()) return "";
    std::ostringstream h;
    h << "<h2>Device model</h2>\n<p class=\"note\">" << htmlEscape(kPredictionIntro) << "</p>\n";
    for (const DevicePrediction& d : devices) {
        h << "<h3>model: " << htmlEscape(d.device) << "</h3>\n<p class=\"note\">"
          << htmlEscape(d.label) << "; compiler " << htmlEscape(d.compiler) << "</p>\n";
        if (!d.error.empty()) {
            h << "<p class=\"note bad\">Not predicted: " << htmlEscape(d.error) << "</p>\n";
            continue;
        }
        h << "<table class=\"predicted\"><tr><th class=\"l\">profile</th><th class=\"l\">pass</th>"
             "<th>predicted ms (model: "
          << htmlEscape(d.device) << ")</th><th class=\"l\">bound</th><th>measured ms (this machine)</th></tr>\n";
        for (const PredictedSession& s : d.sessions) {
            const PredictedVariant& v = s.variants.at(0);
            h << "<tr><td class=\"l\"><b>" << htmlEscape(s.profile) << "</b> " << s.width << "x"
              << s.height << "</td><td class=\"l\">frame"
              << (s.ownDevice ? " (" + budgetText(s, false) + ")" : "")
              << "</td><td" << (s.overBudget() ? " class=\"bad\"" : "") << ">"
              << htmlEscape(v.error.empty() ? ms(v.ms) : "not predicted: " + v.error)
              << "</td><td></td><td>" << ms(v.measuredMs) << "</td></tr>\n";
            for (const PredictedPass& p : v.passes)
                h << "<tr><td></td><td class=\"l\">" << htmlEscape(p.pass) << "</td><td>" << ms(p.ms)
                  << "</td><td class=\"l\">" << htmlEscape(p.bound) << "</td><td>" << ms(p.measuredMs)
                  << "</td></tr>\n";
        }
        h << "</table>\n";
        bool header = false;
        for (const PredictedSession& s : d.sessions) {
            const double pf = s.variants.at(0).ms, mf = s.variants.at(0).measuredMs;
            for (const PredictedDelta& x : s.deltas) {
                if (!header) {
                    h << "<table class=\"predicted-switches\"><tr><th class=\"l\">profile</th><th "
                         "class=\"l\">switch</th><th>predicted &Delta;ms (model: "
                      << htmlEscape(d.device)
                      << ")</th><th>measured &Delta;ms (this machine)</th><th>direction</th></tr>\n";
                    header = true;
                }
                const std::string agree = agreement(x, pf, mf);
                h << "<tr><td class=\"l\">" << htmlEscape(s.profile) << "</td><td class=\"l\">"
                  << htmlEscape(switchText(x)) << "</td><td>" << signedMs(shown(x, x.ms)) << "</td><td>"
                  << signedMs(shown(x, x.measuredMs)) << "</td><td"
                  << (agree == "opposite" ? " class=\"bad\"" : "") << ">" << agree << "</td></tr>\n";
            }
        }
        if (header) h << "</table>\n";
    }
    return h.str();
}

} // namespace pb::bench
