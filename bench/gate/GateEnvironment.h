#pragma once
// What the gate does where the machine differs from the baseline's (bench/baselines/README.md
// "Across machines"): the probe data row, the notes, and which counters may move. GL-free.
#include "GateOutcome.h"
#include "GateRecord.h"

#include <string>

namespace pb::gate {

// Whether a counter (display group + field, "model.fetches" + "irradiance") follows from the
// probe data's values - which probes are valid, so which texels a lookup reads - and so may
// move when the bake does.
bool dependsOnBake(const std::string& group, const std::string& field);

// Adds the probe data row and, where this run's environment differs from the baseline's, a
// note saying what is compared how. Returns the relative tolerance for the bake-dependent
// counters: the suite's isa_counter_tolerance when the baseline was baked on another Embree
// ISA, else 0 (exact).
double compareEnvironment(const GateRecord& baseline, const GateRecord& now, GateOutcome& out);

} // namespace pb::gate
