#pragma once
// What the gate does where the machine differs from the baseline's (bench/baselines/README.md
// "Across machines"): the probe data and bake rows and the notes. GL-free.
#include "GateOutcome.h"
#include "GateRecord.h"

#include <string>

namespace pb::gate {

// Adds two rows and, where this run's environment differs from the baseline's, notes:
// - "probe data": the identity of the probe file every figure was measured with (the one
//   committed beside the baseline). It is the suite's input, so it must match exactly; a
//   mismatch means the baseline and its probe file were not written together (CHANGED).
// - "bake on this machine": this machine's own bake of the suite against the recording
//   machine's. Equal: ok. Different on another CPU or Embree ISA: a note (skipped), since the
//   last bits of a bake differ between CPU vendors and nothing else depends on them. Different
//   on the same CPU and ISA: the code changed the bake (CHANGED; re-record on purpose).
void compareEnvironment(const GateRecord& baseline, const GateRecord& now, GateOutcome& out);

} // namespace pb::gate
