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
// A number or null when not finite.
nlohmann::json finiteOrNull(double v);

} // namespace pb::bench
