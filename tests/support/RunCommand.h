#pragma once
// Runs build/probebench (or any command) the way a user would, capturing output and exit code.
#include <string>
#include <vector>

namespace pb::test {

struct CommandResult {
    int exitCode = -1;    // -1 when the process died from a signal (a crash)
    bool crashed = false;
    std::string output;   // stdout and stderr together
};

// Runs `args` (args[0] is the program) through /bin/sh with each argument quoted.
CommandResult runCommand(const std::vector<std::string>& args);
// Shorthand: the probebench binary with these arguments.
CommandResult runProbebench(const std::vector<std::string>& args);

// probebench with stdout kept apart (through `stdoutFile`): `output` is stderr only, `stdoutText`
// what went to stdout - for `--json` to stdout, which must be one JSON document.
CommandResult runProbebenchSplit(const std::vector<std::string>& args,
                                 const std::string& stdoutFile, std::string& stdoutText);

} // namespace pb::test
