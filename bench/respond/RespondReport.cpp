#include "RespondReport.h"

#include "bench/report/Html.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pb::bench {
namespace {

const char* kColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"};

} // namespace

std::string convergenceSvg(const nlohmann::json& r) {
    // Log10 of the relative error from 1e-3 to 2 against frames after the change.
    const int w = 640, h = 320, left = 50, bottom = 30, top = 10, right = 120;
    std::size_t frames = 1;
    for (const auto& s : r["schedules"])
        frames = std::max(frames, s["error_curve"].size());
    const double lo = -3.0, hi = std::log10(2.0);
    auto x = [&](std::size_t n) { return left + double(n) * (w - left - right) / double(frames); };
    auto y = [&](double e) {
        const double l = std::clamp(std::log10(std::max(e, 1e-3)), lo, hi);
        return top + (hi - l) / (hi - lo) * (h - top - bottom);
    };
    std::ostringstream o;
    o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
      << "' font-family='sans-serif' font-size='11'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n";
    for (double e : {1.0, 0.1, 0.05, 0.01, 0.001}) {
        o << "<line x1='" << left << "' x2='" << w - right << "' y1='" << y(e) << "' y2='" << y(e)
          << "' stroke='#ddd'/><text x='4' y='" << y(e) + 4 << "'>" << e * 100 << "%</text>\n";
    }
    o << "<text x='" << left << "' y='" << h - 8 << "'>frames after the change (0 = before any "
      << "update), error relative to frame 0, log scale</text>\n";
    int i = 0;
    for (const auto& s : r["schedules"]) {
        const char* colour = kColours[i % 5];
        o << "<polyline fill='none' stroke='" << colour << "' stroke-width='1.5' points='";
        std::size_t n = 0;
        for (const auto& e : s["error_curve"])
            o << x(n++) << "," << y(e.get<double>()) << " ";
        o << "'/>\n<text x='" << w - right + 6 << "' y='" << top + 14 * (i + 1) << "' fill='"
          << colour << "'>" << htmlEscape(s["schedule"].get<std::string>()) << "</text>\n";
        ++i;
    }
    if (r.contains("closed_form_hysteresis")) {
        o << "<polyline fill='none' stroke='#888' stroke-dasharray='4 3' points='";
        std::size_t n = 0;
        for (const auto& e : r["closed_form_hysteresis"])
            o << x(n++) << "," << y(e.get<double>()) << " ";
        o << "'/>\n<text x='" << w - right + 6 << "' y='" << top + 14 * (i + 1)
          << "' fill='#888'>0.97^n</text>\n";
    }
    o << "</svg>\n";
    return o.str();
}

std::string respondReportHtml(const nlohmann::json& r) {
    std::ostringstream o;
    o << "<!doctype html><html><head><meta charset='utf-8'><title>probebench respond</title>"
      << "<style>body{font-family:sans-serif}td,th{padding:2px 8px;text-align:right}</style>"
      << "</head><body><h1>Responsive probe updates</h1><p>scene "
      << htmlEscape(r["scene"].get<std::string>()) << ", events:";
    for (const auto& e : r["events"])
        o << " <code>" << htmlEscape(e.get<std::string>()) << "</code>";
    o << "; " << r["width"] << "x" << r["height"] << ", " << r["frames"] << " frames</p>\n"
      << "<h2>Convergence</h2>\n"
      << convergenceSvg(r)
      << "<h2>Figures</h2><table><tr><th>schedule</th><th>t95 frames</th><th>t99 frames</th>"
      << "<th>overshoot</th><th>flicker (CV)</th><th>far drift</th><th>rays/frame</th>"
      << "<th>CPU ms/frame</th><th>bytes uploaded</th></tr>\n";
    for (const auto& s : r["schedules"])
        o << "<tr><td>" << htmlEscape(s["schedule"].get<std::string>()) << "</td><td>" << s["t95_frames"]
          << "</td><td>" << s["t99_frames"] << "</td><td>" << s["overshoot"] << "</td><td>"
          << s["flicker"] << "</td><td>" << s["far_drift"] << "</td><td>" << s["rays_per_frame"]
          << "</td><td>" << s["cpu_ms_per_frame"] << "</td><td>" << s["bytes_uploaded"]
          << "</td></tr>\n";
    o << "</table><p>t95/t99: first frame from which the error stays within 5% / 1% (null: "
         "never in the run). Frames: frames/&lt;schedule&gt;_NNNN.png.</p></body></html>\n";
    return o.str();
}

} // namespace pb::bench
