#include "Format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pb::bench {

namespace {
// One number through `format` (a printf format taking the decimals, then the value); "n/a"
// when not finite. Every formatter below is one of its formats.
std::string printed(const char* format, int decimals, double v) {
    if (!std::isfinite(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, format, decimals, v);
    return buf;
}
} // namespace

std::string fixed(double v, int decimals) {
    return printed("%.*f", decimals, v);
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
    return v == 0 ? "0" : printed("%.*e", 2, v);
}

std::string signedFixed(double v, int decimals) {
    return printed("%+.*f", decimals, v);
}

std::string signedScientific(double v) {
    return v == 0 ? "0" : printed("%+.*e", 2, v);
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
