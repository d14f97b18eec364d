#include "support/RunCommand.h"

#include "support/TestEnv.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace pb::test {

namespace {
std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
} // namespace

CommandResult runCommand(const std::vector<std::string>& args) {
    std::string cmd;
    for (const auto& a : args) cmd += quote(a) + " ";
    cmd += "2>&1";
    CommandResult r;
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int status = ::pclose(pipe);
    if (WIFEXITED(status)) {
        r.exitCode = WEXITSTATUS(status);
        // The shell reports a child killed by a signal as 128 + signal.
        r.crashed = r.exitCode > 128;
    } else {
        r.crashed = true;
    }
    return r;
}

CommandResult runProbebench(const std::vector<std::string>& args) {
    std::vector<std::string> full{binaryPath().string()};
    full.insert(full.end(), args.begin(), args.end());
    return runCommand(full);
}

CommandResult runProbebenchSplit(const std::vector<std::string>& args,
                                 const std::string& stdoutFile, std::string& stdoutText) {
    std::vector<std::string> sh{"/bin/sh", "-c", "out=\"$1\"; shift; exec \"$@\" > \"$out\"",
                                "sh", stdoutFile, binaryPath().string()};
    sh.insert(sh.end(), args.begin(), args.end());
    CommandResult r = runCommand(sh);
    std::ifstream in(stdoutFile, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    stdoutText = s.str();
    return r;
}

} // namespace pb::test
