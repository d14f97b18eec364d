#include "core/TomlRead.h"

#include "core/Error.h"
#include "core/TomlText.h"

namespace pb {

toml::table parseTomlText(std::string_view text, const std::string& path) {
    checkTomlText(text, path); // what toml++ 3.3 cannot read without undefined behaviour
    try {
        return toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw fileError(path + ":" + std::to_string(e.source().begin.line),
                        "TOML syntax error: " + std::string(e.description()));
    }
}

void TomlReader::fail(const toml::source_region& where, const std::string& problem) const {
    throw fileError(path_ + ":" + std::to_string(where.begin.line), problem);
}

void TomlReader::checkKeys(const toml::table& t, const std::set<std::string>& known,
                           const std::string& what) const {
    for (auto&& [k, v] : t) {
        if (known.count(std::string(k.str()))) continue;
        std::string list;
        for (const auto& n : known)
            list += (list.empty() ? "" : ", ") + n;
        fail(k.source(),
             "unknown key '" + std::string(k.str()) + "' in " + what + " (known: " + list + ")");
    }
}

} // namespace pb
