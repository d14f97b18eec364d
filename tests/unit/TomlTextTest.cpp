// checkTomlText: the places where Debian's toml++ 3.3.0 has undefined behaviour on non-ASCII
// text are refused with "path:LINE: problem"; valid UTF-8 in strings and comments passes.
#include "core/TomlText.h"
#include "core/Error.h"

#include <gtest/gtest.h>

namespace {

std::string tomlTextErrorOf(const std::string& text) {
    try {
        pb::checkTomlText(text, "f.toml");
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "(ok)";
}

} // namespace

TEST(TomlText, NonAsciiInStringsAndCommentsIsFine) {
    EXPECT_EQ(tomlTextErrorOf("# caf\xC3\xA9\nname = \"caf\xC3\xA9\"\nb = 'na\xC3\xAFve'\n"),
              "(ok)");
    EXPECT_EQ(tomlTextErrorOf("a = \"\"\"\n\xC3\xA9 \\\" \xC3\xA9\"\"\"\nb = '''\n\xC3\xA9'''\n"),
              "(ok)");
    EXPECT_EQ(tomlTextErrorOf("\"k\xC3\xA9y\" = \"\\\"\xC3\xA9\"\n"),
              "(ok)");                                                // quoted key, escaped quote
    EXPECT_EQ(tomlTextErrorOf("\xEF\xBB\xBFname = \"v\"\n"), "(ok)"); // a UTF-8 BOM
    EXPECT_EQ(tomlTextErrorOf("a = \"\"\"x\"\"\"\"\"\nb = \"\xC3\xA9\"\n"),
              "(ok)"); // quotes before """
}

TEST(TomlText, NonAsciiOutsideStringsIsRefusedWithItsLine) {
    // The fuzzer's input: U+02D9 after a value made toml++ reach __builtin_unreachable().
    EXPECT_EQ(tomlTextErrorOf("a = 1\nprobes = [9, 4, \xCB\x99\n"),
              "f.toml:2: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("n = \"x\" \xC3\xA9\n"),
              "f.toml:1: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("# a comment ends at the line break\n\xC2\xA0= 1\n"),
              "f.toml:2: non-ASCII character outside a string or comment");
}

TEST(TomlText, NonAsciiAfterABackslashInAMultiLineStringIsRefused) {
    // Valid TOML, but toml++ tests the character after a line-ending backslash for whitespace.
    EXPECT_EQ(tomlTextErrorOf("a = \"\"\"x \\\n   \xC3\xA9\"\"\"\n"),
              "f.toml:2: non-ASCII character right after a backslash in a \"\"\" string");
    EXPECT_EQ(tomlTextErrorOf("a = \"\"\"\\\xC3\xA9\"\"\"\n"),
              "f.toml:1: non-ASCII character right after a backslash in a \"\"\" string");
    EXPECT_EQ(tomlTextErrorOf("a = \"\"\"x \\\n   y\xC3\xA9\"\"\"\n"), "(ok)");
}

TEST(TomlText, QuotesAndBracketsInsideAScalarTokenOpenNothing) {
    // The fuzzer's inputs: toml++ reads an invalid number such as 0Ed!e_blen'''_ or
    // +1EEE["-0.0 up to the next value terminator, testing everything on the way (here
    // U+02C7 and U+FEFB) for whitespace.
    EXPECT_EQ(tomlTextErrorOf("c = [0Ed!e_blen'''_\xCB\x87"
                              "ff\n"),
              "f.toml:1: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("c = [0,+1EEE[\"-0.0E\xEF\xBB\xBBH2, 2Y\n"),
              "f.toml:1: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("a.\"b\xC3\xA9\" = [\"x\",'y\xC3\xA9', { k = \"\xC3\xA9\" }]\n"),
              "(ok)");
    EXPECT_EQ(tomlTextErrorOf("d = 1979-05-27 07:32:00Z\nn = \"\xC3\xA9\"\n"), "(ok)");
    EXPECT_EQ(tomlTextErrorOf("d = 1979-05-27 07:32:00\xC3\xA9\n"),
              "f.toml:1: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("[t\xC3\xA9]\n"),
              "f.toml:1: non-ASCII character outside a string or comment");
    EXPECT_EQ(tomlTextErrorOf("[[\"t\xC3\xA9\"]]\nx = [\n# c\xC3\xA9\n1,\n]\n"), "(ok)");
}
