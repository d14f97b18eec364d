#pragma once
// `probebench respond --out-dir`: the HTML page with the convergence curves (relative image
// error against frame, one SVG line per schedule, log scale) and the response figures.
#include <nlohmann/json.hpp>
#include <string>

namespace pb::bench {

// `result` is respond's JSON (schedules[] with "error_curve"). Returns the whole page.
std::string respondReportHtml(const nlohmann::json& result);
// Only the chart (used by the page; tests can check it on its own).
std::string convergenceSvg(const nlohmann::json& result);

} // namespace pb::bench
