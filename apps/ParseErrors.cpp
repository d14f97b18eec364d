#include "ParseErrors.h"

#include "core/Error.h"
#include "core/Suggest.h"

#include <regex>
#include <sstream>

namespace pb::app {
namespace {

std::vector<std::string> commandNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (!sub->get_group().empty()) names.push_back(sub->get_name()); // hidden: group ""
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::vector<std::string> longOptionNames(const CLI::App& cmd) {
    std::vector<std::string> names;
    for (const CLI::Option* o : cmd.get_options())
        for (const auto& n : o->get_lnames())
            names.push_back("--" + n);
    return names;
}

// The first `--name` (before any "=") among `args` that `cmd` does not define; "" if none.
// Only long options: a lone "-" or "-0.5,1,0" may be a value.
std::string unknownLongOption(const CLI::App& cmd, const std::vector<std::string>& args) {
    for (const std::string& a : args) {
        if (a == "--") break;
        if (a.size() < 3 || a.compare(0, 2, "--") != 0) continue;
        const std::string name = a.substr(0, a.find('='));
        if (!cmd.get_option_no_throw(name)) return name;
    }
    return "";
}

// Options renamed, which "did you mean" cannot find by spelling: command, old, new, why.
struct Renamed {
    const char *command, *from, *to, *why;
};
constexpr Renamed kRenamed[] = {
    {"probe", "--view", "--eye-dir", "--view names a view of the scene elsewhere"},
};

std::string renamedHint(const std::string& command, const std::string& option) {
    for (const Renamed& r : kRenamed)
        if (command == r.command && option == r.from)
            return std::string("; renamed '") + r.to + "' (" + r.why + ")";
    return "";
}

std::string typeWords(const std::string& cliType) {
    if (cliType.rfind("INT", 0) == 0) return "an integer";
    if (cliType.rfind("UINT", 0) == 0) return "a non-negative integer";
    if (cliType.rfind("FLOAT", 0) == 0) return "a number";
    return cliType.empty() ? "a value" : cliType;
}

// CLI11's text for each error kind, rewritten as "<option>: <problem>".
std::string rewrite(const CLI::App& cmd, const CLI::ParseError& e) {
    const std::string what = e.what();
    std::smatch m;
    if (std::regex_match(what, m, std::regex("Could not convert: (\\S+) = (.*)"))) {
        const CLI::Option* o = cmd.get_option_no_throw(m[1]);
        return m[1].str() + ": '" + m[2].str() + "' is not " +
               typeWords(o ? o->get_type_name() : "");
    }
    if (std::regex_match(what, m, std::regex("The value (.*) is not an allowed value for (\\S+)")))
        return m[2].str() + ": '" + m[1].str() + "' is not an allowed value";
    if (std::regex_match(what, m, std::regex("(\\S+): \\d+ required (\\S+) missing")))
        return m[1].str() + ": needs a value (" + typeWords(m[2]) + ")";
    if (std::regex_match(what, m, std::regex("Expected (exactly|at least) (\\d+) arguments to (\\S+), got (\\d+)")))
        return m[3].str() + ": expects " + m[1].str() + " " + m[2].str() + " value(s), got " +
               m[4].str();
    if (std::regex_match(what, m, std::regex("(\\S+) is required")))
        return m[1].str() + ": required by '" + cmd.get_name() + "' (probebench " +
               cmd.get_name() + " --help)";
    if (std::regex_match(what, m, std::regex("(\\S+) excludes (\\S+)")))
        return m[1].str() + ": cannot be combined with " + m[2].str();
    if (std::regex_match(what, m, std::regex("(\\S+) requires (\\S+)")))
        return m[1].str() + ": needs " + m[2].str() + " as well";
    if (std::regex_match(what, m, std::regex("The following arguments? (was|were) not expected: (.*)")))
        return m[2].str() + ": unexpected argument for '" + cmd.get_name() +
               "' (options start with --; probebench " + cmd.get_name() + " --help)";
    if (std::regex_match(what, m, std::regex("(\\S+): (.*) not in \\{(.*)\\}"))) {
        std::vector<std::string> choices;
        std::stringstream list(m[3].str());
        for (std::string c; std::getline(list, c, ',');)
            choices.push_back(c);
        return m[1].str() + ": '" + m[2].str() + "' is not one of " + joined(choices) +
               didYouMean(m[2].str(), choices);
    }
    // ValidationError is already "<option>: <problem>"; anything else is at least one line.
    return what;
}

} // namespace

std::string usageMessage(const CLI::App& app, const CLI::ParseError& e,
                         const std::vector<std::string>& args) {
    // The command is the first word that is not an option (the top level has only flags).
    size_t at = 0;
    while (at < args.size() && args[at].rfind("-", 0) == 0)
        ++at;
    const std::vector<std::string> before(args.begin(), args.begin() + long(at));
    if (const std::string bad = unknownLongOption(app, before); !bad.empty())
        return printable(bad + ": unknown option" + didYouMean(bad, longOptionNames(app)) +
                         " (options of a command go after it: probebench <command> --help)");
    const std::vector<std::string> names = commandNames(app);
    if (at == args.size()) return "command: missing (commands: " + joined(names) + ")";
    const CLI::App* cmd = nullptr;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        if (sub->check_name(args[at])) cmd = sub;
    if (!cmd)
        return printable(args[at] + ": unknown command" + didYouMean(args[at], names) +
                         " (commands: " + joined(names) + ")");
    const std::vector<std::string> rest(args.begin() + long(at) + 1, args.end());
    if (const std::string bad = unknownLongOption(*cmd, rest); !bad.empty()) {
        const std::string renamed = renamedHint(cmd->get_name(), bad);
        return printable(bad + ": unknown option of '" + cmd->get_name() + "'" +
                         (renamed.empty() ? didYouMean(bad, longOptionNames(*cmd)) : renamed) +
                         " (probebench " +
                         cmd->get_name() + " --help)");
    }
    return printable(rewrite(*cmd, e));
}

} // namespace pb::app
