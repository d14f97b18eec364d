#pragma once
// The stress sweep's output: JSON for machines, tables for people. GL-free.
//
// JSON (top level): {"command": "stress", "thresholds": {...}, "reference": VARIANT,
//   "variants": [VARIANT...], "cases": [CASE...], "runs": [RUN...], "summary": {...}}
//   VARIANT: {"name", "settings": {key: value for every switch and probes.format}}
//   CASE:    {"name", "group", "stresses", "width", "height", "truth", "frames",
//             "reference_nonfinite_pixels", "reference_error"}
//   RUN:     {"case", "variant", "guards": "as_given"|"off", "symptom", "nonfinite_pixels",
//             "nonfinite_gi_texels", "max_rel", "mean_rel", "median_rel", "error",
//             "culprits": [...], "fixed_by": [...], "finite_with": [...]}
//   summary: {"runs", "broken", "broken_with_guards", "nonfinite_with_guards", "frames"}
#include "stress/StressSweep.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::stress {

nlohmann::json sweepJson(const SweepResult& r);

// A matrix (case x variant run: symptom and median relative error) and the list of broken
// runs with their culprits and the guards that fix them.
std::string sweepText(const SweepResult& r);

} // namespace pb::stress
