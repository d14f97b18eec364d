#pragma once
// "Did you mean" for names the user types (scenes, views, profiles, switches, commands,
// options): a typo should cost one re-run, not a read through the whole list.
#include <string>
#include <string_view>
#include <vector>

namespace pb {

// Levenshtein distance (insert, delete, substitute: 1 each), ASCII case-insensitive.
size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `name` when it is close enough to be a likely typo: at most 1 edit
// for names of up to 3 characters, 2 up to 8, else 3; ties go to the first. "" when none is
// (a wild guess would mislead more than it helps).
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);

// "; did you mean 'x'?" or "" - appended to an error's problem text.
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

} // namespace pb
