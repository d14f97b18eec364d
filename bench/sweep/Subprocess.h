#pragma once
// Child processes for `probebench sweep`: a job or task started with its stdout and stderr
// in files (the sweep's logs), and a short command whose output is read back (sbatch, squeue).
#include <string>
#include <vector>

namespace pb::sweep {

// Starts argv[0] (a path, or a name looked up in PATH) with its stdout written to `outFile`
// and its stderr to `errFile` (both truncated). Returns the pid; throws pb::Error when it cannot.
int startLogged(const std::vector<std::string>& argv, const std::string& outFile,
                const std::string& errFile);

// Waits for `pid`; its exit code, or 128 + the signal that killed it.
int waitFor(int pid);

struct Captured {
    int exitCode = 127; // 127: could not start (not installed)
    std::string output; // stdout and stderr together
};
// Runs argv to completion and returns what it printed. Never throws for a missing program.
Captured capture(const std::vector<std::string>& argv);

// `s` quoted for /bin/sh (single quotes).
std::string shellQuote(const std::string& s);

} // namespace pb::sweep
