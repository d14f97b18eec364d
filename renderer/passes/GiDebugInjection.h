#pragma once
// Test-only faults for proving the regression gate (bench/gate/README.md): environment
// variables, never profile switches, so no profile file or --set can turn them on, and
// `probebench gate` / `bench` warn on stderr while one is set.
//   PB_DEBUG_GI_EXTRA_FETCHES=N (0..16): the apply shader makes N more probe-irradiance fetches
//       per evaluated pixel (a small slowdown; the image does not change).
//   PB_DEBUG_GI_DROP_MANTISSA_BIT=1: the apply shader writes the GI with one mantissa bit less
//       than the target format keeps (an accuracy loss; the speed does not change).
#include "gl/ShaderSource.h"

#include <string>

namespace pb::render {

// The apply shader's extra defines (empty when no variable is set). Throws pb::Error naming
// the variable for a value out of range.
gl::Defines giDebugInjectionDefines();
// "PB_DEBUG_GI_EXTRA_FETCHES=1, ..." for the variables set; "" when none.
std::string giDebugInjectionSummary();

} // namespace pb::render
