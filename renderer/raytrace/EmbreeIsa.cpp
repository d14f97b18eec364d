#include "raytrace/EmbreeIsa.h"

#include "core/Error.h"

#include <cstdlib>

namespace pb::raytrace {
namespace {

#if defined(__x86_64__) || defined(__i386__)
constexpr bool kX86 = true;

// The CPU features Embree 3 requires per ISA (its common/sys/sysinfo.h groups).
bool cpuRuns(const std::string& isa) {
    __builtin_cpu_init();
    const bool sse42 = __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
    const bool avx = sse42 && __builtin_cpu_supports("avx");
    const bool avx2 = avx && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                      __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") &&
                        __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
    if (isa == "sse2") return true; // the x86-64 baseline
    if (isa == "sse4.2") return sse42;
    if (isa == "avx") return avx;
    if (isa == "avx2") return avx2;
    if (isa == "avx512") return avx512;
    return false;
}
#else
constexpr bool kX86 = false;
bool cpuRuns(const std::string&) {
    return false;
}
#endif

std::string& pinned() {
    static std::string isa;
    return isa;
}

std::string checkedIsa(const std::string& isa, const std::string& source) {
    bool known = false;
    for (const char* k : kEmbreeIsas)
        known = known || isa == k;
    if (!known)
        throw Error(source + ": unknown ISA '" + printable(isa) +
                    "' (sse2, sse4.2, avx, avx2 or avx512)");
    if (!cpuRuns(isa)) throw Error(source + ": this CPU cannot run " + isa);
    return isa;
}

// "" when Embree should choose.
std::string requestedIsa() {
    if (!kX86) return "";
    if (const char* v = std::getenv("PB_EMBREE_ISA"); v && *v)
        return checkedIsa(v, "PB_EMBREE_ISA");
    return pinned();
}

} // namespace

void pinEmbreeIsa(const std::string& isa) {
    if (kX86) pinned() = isa.empty() ? isa : checkedIsa(isa, "Embree ISA");
}

std::string embreeDeviceConfig() {
    const std::string isa = requestedIsa();
    return isa.empty() ? std::string() : "isa=" + isa;
}

std::string embreeIsa() {
    if (!kX86) return "native";
    if (std::string isa = requestedIsa(); !isa.empty()) return isa;
    std::string best = "sse2";
    for (const char* k : kEmbreeIsas)
        if (cpuRuns(k)) best = k;
    return best;
}

} // namespace pb::raytrace
