#include "core/TomlText.h"

#include "core/Error.h"

namespace pb {

namespace {

// Follows the TOML grammar as far as toml++ reads it: keys, values, strings, arrays, inline
// tables, comments, and scalar tokens, which toml++ reads up to the next whitespace, ']', '}',
// ',' or '#' (quotes and brackets inside them included). Non-ASCII bytes are checked where
// toml++ would test them for whitespace. At the first thing that is not valid TOML the scan
// stops: toml++ stops there too, with its own error.
class Scanner {
public:
    Scanner(std::string_view text, const std::string& path) : text_(text), path_(path) {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3; // a UTF-8 BOM
    }

    void document() {
        while (more()) {
            skipSpace();
            if (!more()) return;
            if (at('\n') || at('\r') || at('#')) {
                skipLineEnd();
                continue;
            }
            if (at('[')) {
                if (!tableHeader()) return;
            } else if (!keyValue()) {
                return;
            }
            skipSpace();
            if (more() && !at('\n') && !at('\r') && !at('#')) return; // toml++: error
        }
    }

private:
    std::string_view text_;
    const std::string& path_;
    std::size_t i_ = 0;
    int line_ = 1;

    bool more() const { return i_ < text_.size(); }
    bool at(char c) const { return more() && text_[i_] == c; }
    unsigned char peek() const { return static_cast<unsigned char>(text_[i_]); }
    void advance() {
        if (text_[i_] == '\n') ++line_;
        ++i_;
    }

    [[noreturn]] void fail(const char* problem) const {
        throw fileError(path_ + ":" + std::to_string(line_), problem);
    }
    void checkAscii() const {
        if (more() && peek() >= 0x80) fail("non-ASCII character outside a string or comment");
    }

    void skipSpace() {
        while (at(' ') || at('\t'))
            advance();
        checkAscii();
    }
    // Whitespace, line breaks and comments (inside arrays).
    void skipSpaceLinesComments() {
        while (more()) {
            skipSpace();
            if (at('\n') || at('\r'))
                advance();
            else if (at('#'))
                skipLineEnd();
            else
                return;
        }
    }
    // A comment (any bytes) up to and including the line break.
    void skipLineEnd() {
        while (more() && !at('\n'))
            advance();
        if (more()) advance();
    }

    static bool bareKeyChar(unsigned char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    }

    // key = value; false where toml++ stops with an error.
    bool keyValue() {
        if (!key()) return false;
        skipSpace();
        if (!at('=')) return false;
        advance();
        skipSpace();
        return value();
    }

    // Dotted keys: parts are bare keys or strings, '.' between, spaces around the dots.
    bool key() {
        while (true) {
            skipSpace();
            if (at('"') || at('\'')) {
                if (!string()) return false;
            } else if (more() && bareKeyChar(peek())) {
                while (more() && bareKeyChar(peek()))
                    advance();
            } else {
                return false;
            }
            skipSpace();
            if (!at('.')) return true;
            advance();
        }
    }

    bool tableHeader() {
        advance();
        const bool arrayOfTables = at('[');
        if (arrayOfTables) advance();
        if (!key()) return false;
        skipSpace();
        for (int n = arrayOfTables ? 2 : 1; n > 0; --n) {
            if (!at(']')) return false;
            advance();
        }
        return true;
    }

    bool value() {
        checkAscii();
        if (!more()) return false;
        if (at('"') || at('\'')) return string();
        if (at('[')) return array();
        if (at('{')) return inlineTable();
        return scalarToken();
    }

    bool array() {
        advance(); // '['
        while (true) {
            skipSpaceLinesComments();
            if (at(']')) {
                advance();
                return true;
            }
            if (!value()) return false;
            skipSpaceLinesComments();
            if (at(',')) {
                advance();
                continue;
            }
            if (!at(']')) return false;
            advance();
            return true;
        }
    }

    bool inlineTable() {
        advance(); // '{'
        skipSpace();
        if (at('}')) {
            advance();
            return true;
        }
        while (true) {
            if (!keyValue()) return false;
            skipSpace();
            if (at('}')) {
                advance();
                return true;
            }
            if (!at(',')) return false;
            advance();
        }
    }

    static bool terminates(unsigned char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ']' || c == '}' ||
               c == ',' || c == '#';
    }

    // A number, date, boolean, inf or nan: toml++ reads to the next value terminator.
    bool scalarToken() {
        const std::size_t begin = i_;
        while (more() && !terminates(peek())) {
            checkAscii();
            advance();
        }
        // A date and a time may be separated by one space (1979-05-27 07:32:00).
        const std::string_view token = text_.substr(begin, i_ - begin);
        const bool date = token.size() == 10 && token[4] == '-' && token[7] == '-';
        if (date && at(' ') && i_ + 1 < text_.size() && text_[i_ + 1] >= '0' &&
            text_[i_ + 1] <= '9') {
            advance();
            while (more() && !terminates(peek())) {
                checkAscii();
                advance();
            }
        }
        return i_ > begin;
    }

    // Any of the four string kinds; false when unterminated.
    bool string() {
        const char quote = text_[i_];
        std::size_t run = 0;
        while (i_ + run < text_.size() && text_[i_ + run] == quote && run < 3)
            ++run;
        if (run == 2) { // an empty string
            i_ += 2;
            return true;
        }
        const bool multi = run == 3;
        i_ += multi ? 3 : 1;
        while (more()) {
            const char c = text_[i_];
            if (!multi && (c == '\n' || c == '\r')) return false;
            if (c == '\\' && quote == '"') {
                advance();
                if (multi) {
                    // toml++ tests what follows a backslash for whitespace, and after a
                    // line-ending backslash every character up to the next non-space.
                    const std::size_t escaped = i_;
                    while (at(' ') || at('\t') || at('\r') || at('\n'))
                        advance();
                    if (more() && peek() >= 0x80)
                        fail("non-ASCII character right after a backslash in a \"\"\" string");
                    if (i_ == escaped && more()) advance(); // an escape letter, or \"
                    continue;
                }
                if (!more() || at('\n') || at('\r')) return false;
                advance(); // the escaped character
                continue;
            }
            if (c == quote) {
                if (!multi) {
                    advance();
                    return true;
                }
                std::size_t quotes = 0;
                while (i_ + quotes < text_.size() && text_[i_ + quotes] == quote)
                    ++quotes;
                if (quotes >= 3) { // up to two quotes may end the content
                    i_ += quotes;
                    return true;
                }
                i_ += quotes;
                continue;
            }
            advance();
        }
        return false;
    }
};

} // namespace

void checkTomlText(std::string_view text, const std::string& path) {
    Scanner(text, path).document();
}

} // namespace pb
