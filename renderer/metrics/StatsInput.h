#pragma once
// Argument checks and the normal distribution, shared by the statistics functions.
#include <vector>

namespace pb::stats::detail {

// Throws pb::Error "<function>: ..." for an empty sample or a non-finite value.
void requireSample(const char* function, const char* name, const std::vector<double>& v);
// Throws pb::Error unless 0 < confidence < 1.
void requireConfidence(const char* function, double confidence);

double normalCdf(double z);
double normalQuantile(double p); // inverse of normalCdf for p in (0,1)

} // namespace pb::stats::detail
