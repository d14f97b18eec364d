#pragma once
// The Markdown summary `probebench bench` prints on stdout: the speed/accuracy table per
// profile, per-pass medians, and per profile the ablation (what each switch saves and costs).
#include "BenchResult.h"

#include <string>

namespace pb::bench {

std::string markdownSummary(const BenchResult& r);

} // namespace pb::bench
