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

// True when `now` ran on another CPU model or Embree ISA than the baseline's (false when the
// baseline does not record them: an older file is compared strictly).
bool otherMachine(const GateRecord& baseline, const GateRecord& now);

// The cost model's cache replay (`cache.*` lines and hits) on another machine: within this
// share of the baseline's value. Its texel footprints sit on knife edges - a footprint that
// crosses a 64-byte line or not depends on a texel coordinate's last bit - and the last bits
// of CPU arithmetic are not the same everywhere: measured, one ulp of every primary hit's
// distance moves up to 1915 of 7.6 M lines (0.025%), and an AMD EPYC counts 1 line more
// than the Intel Xeon that recorded rooms.json (bench/baselines/README.md "Across
// machines"). A shader change moves far more (one more fetch per lookup: +12.5%). On the
// recording machine every counter stays exact.
inline constexpr double kOtherMachineCacheTolerance = 5e-4;

} // namespace pb::gate
