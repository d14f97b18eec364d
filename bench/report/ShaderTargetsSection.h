#pragma once
// The bench report's section for `bench --targets`: per target, each profile's passes as the
// weak GPU's own compiler sees them (instructions, cycle bound, registers, threads or waves,
// spills) and what each switch changes, beside the measured frame times of this machine.
// Compiler figures are static estimates of the target, not timings (bench/shaders/README.md).
#include "BenchResult.h"

#include <string>

namespace pb::bench {

std::string shaderTargetsHtml(const BenchResult& r);     // "" without targets
std::string shaderTargetsMarkdown(const BenchResult& r); // "" without targets

} // namespace pb::bench
