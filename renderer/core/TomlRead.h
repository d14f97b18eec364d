#pragma once
// What every TOML reader (volume files, camera paths, profiles) does before and around its
// own keys: the text guard (TomlText.h), the parse with its syntax error as one line at the
// offending line, and line errors and the unknown-key check for a file's own readers. One
// place, so the files report alike.
#include <set>
#include <string>
#include <string_view>
#include <toml++/toml.h>

namespace pb {

// checkTomlText, then toml++'s parse. Throws pb::Error "path:LINE: TOML syntax error: ...".
toml::table parseTomlText(std::string_view text, const std::string& path);

// The base of a file's reader: errors at a key's line of that file.
class TomlReader {
public:
    explicit TomlReader(std::string path) : path_(std::move(path)) {}

    // Throws pb::Error "path:LINE: problem", LINE where `where` begins.
    [[noreturn]] void fail(const toml::source_region& where, const std::string& problem) const;

    // Throws at the first key of `t` not in `known`: "unknown key 'k' in WHAT (known: a, b)".
    void checkKeys(const toml::table& t, const std::set<std::string>& known,
                   const std::string& what) const;

    const std::string& path() const { return path_; }

private:
    std::string path_;
};

} // namespace pb
