#pragma once
// The --platform / --device options every rendering command shares, so they read and check
// the same way everywhere.
#include "platforms/Platform.h"

#include <CLI/CLI.hpp>

namespace pb::app {

// Adds --platform (egl|osmesa|glfw, checked) and --device N to `cmd`, writing into `o`.
void addPlatformOptions(CLI::App& cmd, pb::platform::PlatformOptions& o);

} // namespace pb::app
