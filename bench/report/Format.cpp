#include "Format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pb::bench {

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

namespace {
int decimalsFor(double v) {
    double a = std::fabs(v);
    return a >= 100 ? 1 : a >= 1 ? 2 : 3;
}
} // namespace

std::string msWithCi(const stats::Summary& s) {
    int d = decimalsFor(s.median);
    if (!(s.ciLevel > 0)) return fixed(s.median, d) + " [no CI]"; // one sample: no interval
    return fixed(s.median, d) + " [" + fixed(s.ciLow, d) + ", " + fixed(s.ciHigh, d) + "]";
}

std::string shiftWithCi(const stats::Shift& s) {
    int d = decimalsFor(s.estimate);
    std::string sign = s.estimate > 0 ? "+" : "";
    if (!(s.ciLevel > 0)) return sign + fixed(s.estimate, d) + " [no CI]"; // one round
    return sign + fixed(s.estimate, d) + " [" + fixed(s.ciLow, d) + ", " + fixed(s.ciHigh, d) + "]";
}

std::string psnrText(double db) {
    if (std::isinf(db) && db > 0) return "inf";
    return fixed(db, 2);
}

std::string scientific(double v) {
    if (!std::isfinite(v)) return "n/a";
    if (v == 0) return "0";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2e", v);
    return buf;
}

std::string signedFixed(double v, int decimals) {
    if (!std::isfinite(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%+.*f", decimals, v);
    return buf;
}

std::string signedScientific(double v) {
    if (!std::isfinite(v)) return "n/a";
    if (v == 0) return "0";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%+.2e", v);
    return buf;
}

bool significant(const stats::Shift& s) {
    return s.ciLevel > 0 && (s.ciLow > 0 || s.ciHigh < 0);
}

std::vector<std::string> sectionNames(const BenchResult& r) {
    std::vector<std::string> names;
    for (const SessionResult& s : r.sessions)
        for (const VariantResult& v : s.variants)
            for (const SectionTiming& t : v.sections)
                if (std::find(names.begin(), names.end(), t.name) == names.end())
                    names.push_back(t.name);
    return names;
}

} // namespace pb::bench
