#pragma once
// The report's charts as inline SVG (no script, no network): the speed/accuracy Pareto chart
// and per-pass stacked bars.
#include <string>
#include <utility>
#include <vector>

namespace pb::bench {

struct ParetoPoint {
    std::string label;
    double deltaMs = 0, ciLow = 0, ciHigh = 0; // vs reference, with its interval
    double flip = 0;                           // LDR-FLIP mean vs reference
    bool isProfile = true;                     // false: one switch applied to reference
    std::string tag;                           // short mark drawn on non-profile points ("3")
};

// x = delta ms vs reference (left = faster), y = FLIP (up = worse); the non-dominated points
// (nothing both faster and more accurate) joined by a dashed front. Profiles are labelled by
// name, other points by their tag (the caller lists what the tags mean).
// `ciLabel` names the intervals' level on the axis (CiLevels.h: "96.9% CI").
std::string paretoSvg(const std::vector<ParetoPoint>& points, const std::string& ciLabel = "CI");
// Indices of the non-dominated points, sorted by deltaMs.
std::vector<size_t> paretoFront(const std::vector<ParetoPoint>& points);

struct StackedBar {
    std::string label;
    std::vector<std::pair<std::string, double>> segments; // (pass name, ms) in frame order
    double total = 0;                                     // whole frame ms (>= segment sum)
};

// One horizontal bar per profile, a colour per pass name (legend on top).
std::string stackedBarsSvg(const std::vector<StackedBar>& bars);

} // namespace pb::bench
