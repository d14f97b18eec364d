#pragma once
// One exception type for every user-facing failure: the message is printed as is, on one line,
// by the command-line app (exit code 1; 2 for a UsageError). It names the file (or option) and the problem.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pb {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An option's value that is out of range or not one of its choices (`--width 0`, `--set
// gi.resolution=halve`): a usage error, so the app exits 2 as for a command line that does not
// parse (README, "Errors and exit codes"). Everything else stays an Error (exit 1).
class UsageError : public Error {
public:
    using Error::Error;
};

// `text` with control characters written as escapes ("\n", "\x01"): names read from a file
// (a glTF mesh, a volume, a probe-file scenario) may contain anything, and an error that
// quotes them must stay one line on the terminal.
inline std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(u));
            out += hex;
        } else {
            out += c;
        }
    }
    return out;
}

// "path: message" - the house style for errors about a file. Always one line: whatever the
// message quotes from the file is escaped.
inline Error fileError(const std::string& path, const std::string& message) {
    return Error(printable(path) + ": " + printable(message));
}

} // namespace pb
