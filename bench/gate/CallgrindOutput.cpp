#include "CallgrindOutput.h"

#include "core/Error.h"

#include <algorithm>
#include <fstream>
#include <regex>

namespace pb::gate {

CallgrindDump readCallgrindDump(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw fileError(path, "cannot read the callgrind output");
    CallgrindDump d;
    bool totals = false;
    std::string line;
    const std::string request = "desc: Trigger: Client Request: ";
    while (std::getline(in, line)) {
        if (line.rfind(request, 0) == 0) d.trigger = line.substr(request.size());
        if (line.rfind("totals:", 0) == 0) {
            d.instructions = std::stoull(line.substr(7));
            totals = true;
        }
    }
    if (!totals) throw fileError(path, "no 'totals:' line (not a finished callgrind dump)");
    return d;
}

std::vector<std::pair<std::string, Counters>>
callgrindProfiles(const std::vector<CallgrindDump>& dumps) {
    std::vector<std::pair<std::string, Counters>> out;
    for (const CallgrindDump& d : dumps) {
        const size_t slash = d.trigger.find('/');
        if (slash == std::string::npos || slash == 0) continue;
        const std::string profile = d.trigger.substr(0, slash),
                          section = d.trigger.substr(slash + 1);
        auto p =
            std::find_if(out.begin(), out.end(), [&](const auto& x) { return x.first == profile; });
        if (p == out.end()) p = out.insert(out.end(), {profile, {{"frame", 0}}});
        auto s = std::find_if(p->second.begin(), p->second.end(),
                              [&](const auto& x) { return x.first == section; });
        if (s == p->second.end()) s = p->second.insert(p->second.end(), {section, 0});
        s->second += std::int64_t(d.instructions);
        p->second.front().second += std::int64_t(d.instructions);
    }
    return out;
}

CallgrindKey callgrindKey(const std::string& glVersion, const std::string& glRenderer,
                          const std::string& compiler, const std::string& valgrindVersion) {
    auto match = [](const std::string& s, const std::regex& re) {
        std::smatch m;
        return std::regex_search(s, m, re) ? m[1].str() : std::string("unknown");
    };
    CallgrindKey k;
    k.mesa = "Mesa " + match(glVersion, std::regex(R"(Mesa ([0-9][0-9A-Za-z.\-]*))"));
    k.llvm = match(glRenderer, std::regex(R"(LLVM ([0-9][0-9.]*))"));
    k.compiler = compiler.empty() ? "unknown" : compiler;
    k.valgrind = valgrindVersion.empty() ? "unknown" : valgrindVersion;
    return k;
}

} // namespace pb::gate
