#include "TunedProfile.h"

#include "profile/SwitchTable.h"

#include <sstream>
#include <toml++/toml.h>

namespace pb::bench {

std::string tunedProfileToml(const profile::Profile& base, const profile::Profile& tuned,
                             const TunedProfileInfo& info) {
    toml::table gi;
    for (const profile::SwitchInfo& s : profile::switchTable()) {
        if (s.get(tuned) == s.get(base)) continue;
        const std::string leaf = s.key.substr(s.key.find('.') + 1); // "gi.resolution" -> ...
        if (s.kind == profile::SwitchKind::Number)
            gi.insert(leaf, std::stod(s.get(tuned)));
        else
            gi.insert(leaf, s.get(tuned));
    }
    // Separate tables so `inherit` and `description` come first (toml++ sorts a table's keys).
    const toml::table inherit{{"inherit", info.inherit}};
    const toml::table description{{"description", info.description}};
    toml::table root{
        {"output", toml::table{{"width", info.width}, {"height", info.height}}},
        {"budget", toml::table{{"frame_ms", info.budgetMs}, {"gi_memory_mib", info.budgetMiB}}}};
    if (!gi.empty()) root.insert("gi", std::move(gi));
    std::ostringstream out;
    for (const std::string& c : info.comments)
        out << "# " << c << "\n";
    out << inherit << "\n" << description << "\n\n" << root << "\n";
    return out.str();
}

} // namespace pb::bench
