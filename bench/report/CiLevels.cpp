#include "CiLevels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pb::bench {

namespace {
std::string percentDown(double level) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", std::floor(level * 1000.0 + 1e-9) / 10.0);
    std::string s = buf;
    if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
    return s + "%";
}
} // namespace

std::string ciLabel(const std::vector<double>& levels) {
    if (levels.empty()) return "CI";
    const auto [lo, hi] = std::minmax_element(levels.begin(), levels.end());
    if (!(*hi > 0)) return "no CI";
    if (*hi - *lo < 1e-9) return percentDown(*lo) + " CI";
    return "CI ≥ " + percentDown(*lo);
}

std::vector<double> frameCiLevels(const BenchResult& r) {
    std::vector<double> out;
    for (const SessionResult& s : r.sessions)
        for (const VariantResult& v : s.variants)
            if (v.ok()) out.push_back(v.frameMs.ciLevel);
    return out;
}

std::vector<double> deltaCiLevels(const BenchResult& r) {
    std::vector<double> out;
    for (const SessionResult& s : r.sessions)
        for (const DeltaResult& d : s.deltas)
            if (d.measured) out.push_back(d.ms.ciLevel);
    return out;
}

double deltaLevelOfRounds(int rounds) {
    if (rounds < 1) return 0.0;
    std::vector<double> a(static_cast<size_t>(rounds)), b(static_cast<size_t>(rounds));
    for (int i = 0; i < rounds; ++i) {
        a[size_t(i)] = i;
        b[size_t(i)] = 2.0 * i + 1.0; // distinct differences: no ties
    }
    return stats::pairedShift(a, b, 0.95).ciLevel;
}

int roundsFor95() {
    int n = 1;
    while (deltaLevelOfRounds(n) < 0.95)
        ++n;
    return n;
}

std::string roundsWarning(int rounds) {
    const double level = deltaLevelOfRounds(rounds);
    if (level >= 0.95) return "";
    const std::string what = level > 0 ? "give delta intervals of " + percentDown(level) +
                                             " at most, not 95%"
                                       : "give no interval at all";
    return std::to_string(rounds) + " round(s) " + what + "; --rounds " +
           std::to_string(roundsFor95()) + " or more give 95%";
}

} // namespace pb::bench
