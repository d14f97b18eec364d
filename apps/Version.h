#pragma once
// `probebench --version`: what a bug report or a benchmark result needs to say which build it
// came from - without a GL context, so it works where `info` cannot start one.
#include <string>

namespace pb::app {

// The multi-line text --version prints: commit, build type, Embree, Mesa.
std::string versionText();

} // namespace pb::app
