#pragma once
// report.html: one self-contained file (inline CSS and SVG, heat maps as data: URIs, no
// script, nothing fetched): the speed/accuracy table per profile, the Pareto chart, per-pass
// stacked bars, the ablation per profile, the FLIP heat maps and the run's context.
#include "BenchResult.h"

#include <string>

namespace pb::bench {

// Reads the heat-map PNGs named in the result (AccuracyResult::heatmapFile) to inline them.
std::string htmlReport(const BenchResult& r);

} // namespace pb::bench
