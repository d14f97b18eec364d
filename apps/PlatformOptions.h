#pragma once
// The --platform / --device options every rendering command shares, so they read and check
// the same way everywhere.
#include "platforms/Platform.h"

#include <CLI/CLI.hpp>

namespace pb::app {

// Adds --platform (egl|osmesa|glfw, checked) and --device N to `cmd`, writing into `o`.
void addPlatformOptions(CLI::App& cmd, pb::platform::PlatformOptions& o);

// `o` for a command that times frames (bench, tune, stress): a non-debug context, since
// KHR_debug's checks cost time in the driver (the gate's worker does the same). GL errors are
// still caught (DebugOutput also polls glGetError); render and the tests keep the debug context.
inline pb::platform::PlatformOptions timingPlatform(pb::platform::PlatformOptions o) {
    o.debugContext = false;
    return o;
}

} // namespace pb::app
