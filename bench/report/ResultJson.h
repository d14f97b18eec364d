#pragma once
// The machine-readable result of `probebench bench --json` (schema "probebench.bench/1";
// bench/README.md documents the fields). Non-finite numbers (PSNR of identical images) are
// written as null.
#include "BenchResult.h"

#include <nlohmann/json.hpp>

namespace pb::bench {

nlohmann::json summaryJson(const stats::Summary& s);
nlohmann::json shiftJson(const stats::Shift& s);
nlohmann::json benchJson(const BenchResult& r);

// Per frame: the summed exclusive time of every GI section (GiSections.h: the "gi-" sections
// and the upsample).
std::vector<double> giPassSamples(const VariantResult& v);
// GI ms (giPassSamples' median) over the fetch floor's median: per texel, as both are timed;
// NaN without a floor.
double giOverFloor(const VariantResult& v);
// The same per lookup (issue 17): GI ms per evaluation over the floor's ms per texel (it does
// one lookup per texel) = giOverFloor * giTexels / giEvaluations. A naive multi-volume pass
// evaluates some texels once per volume, so per texel it sits that much above per evaluation.
// NaN without a floor or without counted evaluations.
double giOverFloorPerEvaluation(const VariantResult& v);
// A number or null when not finite.
nlohmann::json finiteOrNull(double v);

} // namespace pb::bench
