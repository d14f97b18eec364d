#pragma once
// A check every TOML reader runs on the raw text before toml++ parses it (volume files now,
// profiles the same way): Debian's toml++ 3.3.0 reaches __builtin_unreachable() (undefined
// behaviour: anything may happen) when it tests some non-ASCII code points for whitespace -
// U+00A1..U+0499 and U+FB06..U+FEFE, e.g. an "é" after a value. It does so only where TOML
// forbids non-ASCII anyway (outside strings and comments), or right after a backslash in a
// multi-line basic string. Those places are refused here with a one-line error.
#include <string>
#include <string_view>

namespace pb {

// Throws pb::Error "path:LINE: problem" for a non-ASCII byte outside strings and comments, or
// after a backslash (and any whitespace) in a """multi-line""" string. Everything else,
// including malformed TOML, is left for the parser to report.
void checkTomlText(std::string_view text, const std::string& path);

} // namespace pb
