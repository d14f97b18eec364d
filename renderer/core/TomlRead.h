#pragma once
// What every TOML reader (volume files, camera paths, profiles) does before and around its
// own keys: the text guard (TomlText.h), the parse with its syntax error as one line at the
// offending line, and the unknown-key check. One place, so the files report alike.
#include <set>
#include <string>
#include <string_view>
#include <toml++/toml.h>

namespace pb {

// checkTomlText, then toml++'s parse. Throws pb::Error "path:LINE: TOML syntax error: ...".
toml::table parseTomlText(std::string_view text, const std::string& path);

// Throws pb::Error "path:LINE: problem", LINE where `where` begins.
[[noreturn]] void failAt(const std::string& path, const toml::source_region& where,
                         const std::string& problem);

// Throws at the first key of `t` not in `known`: "unknown key 'k' in WHAT (known: a, b)".
void checkTomlKeys(const std::string& path, const toml::table& t,
                   const std::set<std::string>& known, const std::string& what);

} // namespace pb
