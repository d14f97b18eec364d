#pragma once
// Number checks for options whose failure reads as a sentence: CLI::PositiveNumber printed its
// range as "0.000000 to 1797693134862315...(300 digits)".
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <string>

namespace pb::app {

// Accepts a finite number greater than 0 (`strictly`) or not less than 0.
inline CLI::Validator numberAtLeastZero(bool strictly) {
    return CLI::Validator(
        [strictly](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
            if (!(v > 0.0) && (strictly || !(v == 0.0)))
                return "'" + text + "' must be " + (strictly ? "more than 0" : "0 or more");
            return "";
        },
        strictly ? "> 0" : ">= 0");
}

} // namespace pb::app
