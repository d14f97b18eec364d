#pragma once
// CLI11's parse errors in the house format (README, "Errors and exit codes"): one line,
// `<option>: <problem>`, exit 2 (usage) - instead of CLI11's two-line text and its own exit
// codes (104, 106, 109, ...), which scripts could not tell from a failed run.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace pb::app {

inline constexpr int kUsageExit = 2;

// The message for `e`, raised while `app` parsed `args` (argv without the program name):
// "<option or command>: <problem>", with "did you mean" for an unknown command or option.
// An unknown option is reported before whatever CLI11 raised first (it checks required options
// before it looks at the extras, so `gate --quik` used to say "--baseline is required").
std::string usageMessage(const CLI::App& app, const CLI::ParseError& e,
                         const std::vector<std::string>& args);

} // namespace pb::app
