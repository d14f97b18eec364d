#pragma once
// Subcommands register themselves here (one file per command in apps/), so adding a command
// means adding one file, not editing main.cpp.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace pb::app {

struct Command {
    std::string name;
    std::string summary;
    int order = 100; // position in --help
    // Adds the command's options to `cmd` and returns the function that runs it (exit code).
    std::function<std::function<int()>(CLI::App& cmd)> setup;
};

std::vector<Command>& commands();

struct RegisterCommand {
    explicit RegisterCommand(Command c) { commands().push_back(std::move(c)); }
};

} // namespace pb::app
