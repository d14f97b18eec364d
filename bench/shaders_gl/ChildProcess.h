#pragma once
// A child process run to completion with a time limit: `probebench shaders` runs one worker per
// target, each with its own preloaded shim, and a shim that hangs (lima's fence wait) must not
// hang the whole run.
#include <string>
#include <vector>

namespace pb::shaders {

struct ChildResult {
    int exitCode = -1;     // 128 + signal when killed
    bool timedOut = false; // killed at the limit
};

// Runs argv (argv[0] a path) with `env` ("NAME=value") added to this process's environment,
// stdout and stderr both written to `logFile`. Throws pb::Error when it cannot start.
ChildResult runChild(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                     const std::string& logFile, int timeoutSeconds);

} // namespace pb::shaders
