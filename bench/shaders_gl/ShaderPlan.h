#pragma once
// The bench's plan (bench/report/AblationPlan.h) as `probebench shaders` compiles it: every
// distinct variant of every session once, and every single-switch pair (a switch reverted in
// a profile, or applied to the reference) as a SwitchPair, so each switch's change in
// instructions, registers and spills is read off programs that differ in that switch only.
#include "ShaderCollector.h"
#include "bench/report/AblationPlan.h"

#include <vector>

namespace pb::shaders {

// With `fusedTwins`, every variant with gi.loops=split is followed by its twin with
// gi.loops=fused (id: fusedTwinId(id), role "twin"): the compilers count a loop's body once, so
// the device model (bench/devicemodel) reads the split program's arithmetic off the written-out
// fused one. Twins are in no table and no pair.
std::vector<PlannedVariant> plannedVariants(const bench::BenchPlan& plan, bool fusedTwins = false);
std::vector<SwitchPair> switchPairs(const bench::BenchPlan& plan);

} // namespace pb::shaders
