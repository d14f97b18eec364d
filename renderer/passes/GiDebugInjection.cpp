#include "passes/GiDebugInjection.h"

#include "core/Error.h"

#include <cstdlib>

namespace pb::render {

namespace {

// The variable's integer value in [0, max]; 0 when unset or empty.
int envInt(const char* name, int max) {
    const char* v = std::getenv(name);
    if (!v || !*v) return 0;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    if (*end || n < 0 || n > max)
        throw Error(std::string(name) + ": must be an integer in 0.." + std::to_string(max) +
                    " (test-only fault injection)");
    return int(n);
}

int extraFetches() {
    return envInt("PB_DEBUG_GI_EXTRA_FETCHES", 16);
}
bool dropMantissaBit() {
    return envInt("PB_DEBUG_GI_DROP_MANTISSA_BIT", 1) != 0;
}

} // namespace

gl::Defines giDebugInjectionDefines() {
    gl::Defines d;
    if (const int n = extraFetches()) d["GI_DEBUG_EXTRA_FETCHES"] = std::to_string(n);
    if (dropMantissaBit()) d["GI_DEBUG_DROP_MANTISSA_BIT"] = "";
    return d;
}

std::string giDebugInjectionSummary() {
    std::string s;
    if (const int n = extraFetches()) s = "PB_DEBUG_GI_EXTRA_FETCHES=" + std::to_string(n);
    if (dropMantissaBit())
        s += std::string(s.empty() ? "" : ", ") + "PB_DEBUG_GI_DROP_MANTISSA_BIT=1";
    return s;
}

} // namespace pb::render
