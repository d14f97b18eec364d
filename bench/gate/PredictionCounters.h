#pragma once
// The device model's predictions (bench/devicemodel) as the gate keeps them: per suite profile
// on its own device ([budget] model), per pass the predicted time and each unit's share as exact
// integers (nanoseconds, rounded), under the target "model:<device>" of the shader record. The
// model is deterministic, so a shader change (a compiler's count) or a fetch-pattern change (the
// cost model's replay) shows up as a changed counter (bench/gate/README.md "Shader statistics").
// GL-free.
#include "GateRecord.h"
#include "bench/report/DevicePrediction.h"

namespace pb::gate {

// Counters per pass: predicted_ns, alu_ns, texture_ns, memory_ns, rop_ns; and a pass "frame"
// with the frame's predicted_ns. Variants that could not be predicted are left out.
ShaderTargetRecord predictionRecord(const bench::DevicePrediction& p);

} // namespace pb::gate
