#include "core/Suggest.h"

#include <algorithm>
#include <cctype>

namespace pb {

size_t editDistance(std::string_view a, std::string_view b) {
    auto lower = [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); };
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            const size_t substitute = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
            row[j] = std::min({above + 1, row[j - 1] + 1, substitute});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
    const size_t limit = name.size() <= 3 ? 1 : name.size() <= 8 ? 2 : 3;
    std::string best;
    size_t bestDistance = limit + 1;
    for (const std::string& c : candidates) {
        const size_t d = editDistance(name, c);
        if (d < bestDistance && c != name) {
            best = c;
            bestDistance = d;
        }
    }
    return best;
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    const std::string best = closestName(name, candidates);
    return best.empty() ? "" : "; did you mean '" + best + "'?";
}

} // namespace pb
