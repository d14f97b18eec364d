// probebench: the command-line entry point. Each subcommand lives in its own apps/cmd_*.cpp.
#include "CommandRegistry.h"
#include "ParseErrors.h"
#include "Version.h"
#include "core/Error.h"
#include "core/ReuseFreedMemory.h"

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace pb::app {
std::vector<Command>& commands() {
    static std::vector<Command> all;
    return all;
}
} // namespace pb::app

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // bakes free and reallocate large textures (ReuseFreedMemory.h)
    using namespace pb::app;
    CLI::App app{"probebench - a testbed for baked probe global illumination (DDGI) on weak GPUs.\n"
                 "Renders glTF or built-in scenes through OpenGL ES 3 (EGL headless by default,\n"
                 "OSMesa, or a GLFW window), bakes probes with Embree and measures what each\n"
                 "GI optimization saves in frame time and costs in accuracy.",
                 "probebench"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Show help for every subcommand");
    app.set_version_flag("--version", versionText,
                         "Print the commit, build type, Embree and Mesa versions and exit");
    app.footer("Run `probebench <command> --help` for a command's options.\n"
               "Errors are one line, `probebench: error: <file or option>: <problem>`; exit 2\n"
               "for a usage error (unknown option or command, a value that does not parse),\n"
               "1 for any other failure (README, \"Errors and exit codes\").");

    auto& cmds = commands();
    std::stable_sort(cmds.begin(), cmds.end(),
                     [](const Command& a, const Command& b) { return a.order < b.order; });
    std::map<CLI::App*, std::function<int()>> runners;
    for (auto& c : cmds) {
        CLI::App* sub = app.add_subcommand(c.name, c.summary);
        runners[sub] = c.setup(*sub);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help, --help-all and --version arrive as "errors" with exit code 0.
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "probebench: error: "
                  << usageMessage(app, e, std::vector<std::string>(argv + 1, argv + argc)) << "\n";
        return kUsageExit;
    } catch (const pb::Error& e) { // a check once the line is parsed (JsonOption's output folder)
        std::cerr << "probebench: error: " << e.what() << "\n";
        return 1;
    }
    try {
        for (auto& [sub, run] : runners)
            if (sub->parsed()) return run();
    } catch (const pb::UsageError& e) {
        std::cerr << "probebench: error: " << e.what() << "\n";
        return kUsageExit;
    } catch (const pb::Error& e) {
        std::cerr << "probebench: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "probebench: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
