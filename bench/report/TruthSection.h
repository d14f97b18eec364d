#pragma once
// The report's "against the ground truth" section (`bench --truth`): per session a table of
// every variant (reference, profile, ablation rows) with FLIP, PSNR and relative MSE against the
// path-traced truth, and the truth, reference and profile frames side by side with their FLIP
// heat maps. Empty strings when the run had no truth.
#include "BenchResult.h"

#include <string>

namespace pb::bench {

std::string truthHtml(const BenchResult& r);
std::string truthMarkdown(const BenchResult& r);

} // namespace pb::bench
