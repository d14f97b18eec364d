#pragma once
// One exception type for every user-facing failure: the message is printed as is, on one line,
// by the command-line app (exit code 1). It names the file (or option) and the problem.
#include <stdexcept>
#include <string>

namespace pb {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "path: message" - the house style for errors about a file.
inline Error fileError(const std::string& path, const std::string& message) {
    return Error(path + ": " + message);
}

} // namespace pb
