#pragma once
// `--json [FILE]`, one convention in every command (issue 25, item 9): `--json` alone or
// `--json -` prints the JSON on stdout, `--json FILE` writes it to FILE (atomically, nothing
// on a failure). While JSON goes to stdout, everything else a command prints for people goes to
// stderr (StdoutToStderr), so stdout parses as JSON.
//
// CLI11 note: the option takes at most one value, and a following word that is not an option
// becomes that value; none of the commands has positional arguments, so nothing else can be
// swallowed (tests/cli/JsonOptionCliTest.cpp runs both forms).
#include <CLI/CLI.hpp>

#include <string>

namespace pb::app {

class JsonOption {
public:
    // Adds `--json [FILE]` to `cmd`; `what` says what the JSON holds ("the full result").
    void add(CLI::App& cmd, const std::string& what);

    explicit operator bool() const { return option_ && option_->count() > 0; }
    bool toStdout() const { return bool(*this) && (value_.empty() || value_ == "-"); }
    // The file to write; empty when the JSON goes to stdout or was not asked for.
    std::string file() const { return bool(*this) && !toStdout() ? value_ : std::string(); }

private:
    std::string value_;
    bool mkdir_ = false; // the command's --mkdir when it has none of its own
    const CLI::Option* option_ = nullptr;
};

// Writes `text` where `json` says: the real stdout (also under StdoutToStderr) or FILE.
void writeJson(const JsonOption& json, const std::string& text);

// While alive, file descriptor 1 is stderr (printf and std::cout alike), so a command's
// tables, progress and notes cannot mix with the JSON; writeJson still reaches the real
// stdout. Does nothing unless `active`. Child processes inherit the redirected stdout.
class StdoutToStderr {
public:
    explicit StdoutToStderr(bool active);
    ~StdoutToStderr();
    StdoutToStderr(const StdoutToStderr&) = delete;
    StdoutToStderr& operator=(const StdoutToStderr&) = delete;

private:
    int saved_ = -1;
};

} // namespace pb::app
