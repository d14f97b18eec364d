#pragma once
// `probebench --version`: what a bug report or a benchmark result needs to say which build it came
// from - without a GL context, so it works where `info` cannot start one.
#include <string>

namespace pb::app {

// Generated at build time (cmake/BuildInfo.cmake).
std::string buildCommit();
std::string buildType();
std::string buildMesa();

// The multi-line text --version prints.
std::string versionText();

} // namespace pb::app
