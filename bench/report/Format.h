#pragma once
// Number formatting shared by the Markdown summary and the HTML report, so both show the
// same figures the same way.
#include "BenchResult.h"

#include <string>

namespace pb::bench {

std::string fixed(double v, int decimals);      // "12.35"; "n/a" when not finite
// "12.3 [12.1, 12.6]"; "12.3 [no CI]" for an interval of no coverage (one sample). The level
// goes in the column's header (CiLevels.h: ciLabel).
std::string msWithCi(const stats::Summary& s);
std::string shiftWithCi(const stats::Shift& s); // "-3.21 [-3.50, -2.90]", "+7.71 [no CI]"
std::string psnrText(double db);                // "34.52" or "inf" (identical)
std::string scientific(double v);               // "1.23e-04"
std::string signedFixed(double v, int decimals); // "+0.0012", "-0.0030"; "n/a" when not finite
std::string signedScientific(double v);          // "+1.23e-04", "-4.00e-05"
// Whether the interval excludes zero: the delta is a measured difference, not noise (never
// without an interval).
bool significant(const stats::Shift& s);
// Pass names in first-seen order over every ok variant of every session.
std::vector<std::string> sectionNames(const BenchResult& r);

} // namespace pb::bench
