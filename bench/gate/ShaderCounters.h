#pragma once
// The weak GPUs' compiler statistics (`probebench shaders`, bench/shaders/) as the gate keeps
// them: per target, suite profile and pass, the pass's heaviest fragment program's figures as
// exact integers, so that a shader change that costs one instruction on one compiler fails the
// gate (bench/gate/README.md "Shader statistics"). GL-free.
#include "GateRecord.h"
#include "bench/shaders/ShaderStatistics.h"

#include <string>
#include <vector>

namespace pb::gate {

// One fragment stage's figures under one name for every driver; a figure the driver does not
// report is absent: instructions, milli_cycles (Mali's cycle bound x 1000, rounded: the
// compilers print it with at most 6 decimals, so the integer is as deterministic as the text
// and compares exactly), spills, fills, registers_full, registers_half (freedreno's vec4
// registers; v3d's max-temps and nouveau's gpr count as full), occupancy (waves or threads in
// flight), loops, local_bytes (nouveau's spill space).
Counters shaderStageCounters(const shaders::StageStatistics& fragment);

// The record of `run` keyed by its Mesa version and `drivers` (the install's, as built): per
// target that ran, the passes of the variants of `profiles` (the suite's, each compiled as
// itself, no ablation) in build order. A target with an error is left out; the caller reports
// it (shaders::shaderRunProblems).
ShaderRecord shaderRecordOf(const shaders::ShaderStatisticsRun& run,
                            const std::vector<std::string>& drivers,
                            const std::vector<std::string>& profiles);

// The short names the gate's table shows for the counters above ("inst", "mcycles", ...).
std::string shaderCounterLabel(const std::string& counter);

} // namespace pb::gate
