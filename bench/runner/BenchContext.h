#pragma once
// Where a benchmark ran, recorded in every result: platform, GL strings, driver version, CPU,
// thread count (LP_NUM_THREADS), commit, date, load average. Needs a current GL context.
#include "gl/Capabilities.h"
#include "platforms/Platform.h"

#include <nlohmann/json.hpp>

namespace pb::bench {

nlohmann::json benchContext(const platform::Platform& platform, const gl::GlCaps& caps);
// /proc/cpuinfo's first "model name" ("AMD EPYC"), "unknown" elsewhere.
std::string cpuModel();
// "0.52 0.61 0.70" from /proc/loadavg ("unknown" elsewhere).
std::string loadAverage();
// The source tree's commit at build time (git describe --always --dirty), refreshed at every
// build by runner/BuildInfo.cmake; also `probebench --version`.
std::string gitCommit();
// Whether the current context is a debug context (GL_CONTEXT_FLAG_DEBUG_BIT); null where the
// GL version cannot say (ES < 3.2, GL < 4.3). Recorded as `debug_context` in every result.
nlohmann::json debugContextFlag(const gl::GlCaps& caps);

} // namespace pb::bench
