#pragma once
// Beyond medians (issue 25, item 4): frame-time percentiles (p50, p90, p99) per variant, and
// flags that say when a delta's two sides are not one steady distribution each - bimodal
// frame times (a device switching clocks, a compositor stealing every other frame) or a
// variance that changed between them - which a median delta alone hides. Pinpoint users look
// for these next to the delta.
#include "BenchResult.h"

#include <string>
#include <vector>

namespace pb::bench {

// Type-7 quantile (as stats::summarize's quartiles), q in [0, 1]; NaN for no samples.
double percentile(std::vector<double> samples, double q);

// Sarle's bimodality coefficient (skewness^2 + 1) / (excess kurtosis + 3 (n-1)^2/((n-2)(n-3)));
// above 5/9 (the uniform distribution's) suggests two modes. NaN below 4 samples or with no
// variance.
double bimodalityCoefficient(const std::vector<double>& samples);
inline constexpr double kBimodalAbove = 5.0 / 9.0;
// Variances whose ratio passes this are flagged (a doubled standard deviation).
inline constexpr double kVarianceRatioFlag = 4.0;

// "" or the delta's flags, e.g. "bimodal: on; variance x6.3" - `off` and `on` are the delta's
// two variants, judged from their per-frame samples.
std::string noiseFlags(const VariantResult& off, const VariantResult& on);

} // namespace pb::bench
