#include "TimingTrust.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace pb::bench {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

} // namespace

std::string machineWarning(const BenchResult& r) {
    std::string out;
    std::vector<std::string> seen; // sessions timed in the same rounds share one state
    for (const SessionResult& s : r.sessions) {
        const std::string noisy = noisyMachineText(s.machineBefore, s.machineAfter);
        if (noisy.empty() || std::find(seen.begin(), seen.end(), noisy) != seen.end()) continue;
        seen.push_back(noisy);
        out += (out.empty() ? "" : "; ") + noisy + " while timing " + s.session.profile.name +
               "'s rounds";
    }
    if (out.empty()) return out;
    return "the machine was not quiet: " + out +
           ". Deltas are paired within rounds, but their intervals widen and a noisy machine "
           "can shift them; rerun on a quieter one (--require-quiet refuses to time instead)";
}

bool budgetJudged(const profile::PlatformProfile& p, const std::string& glRenderer) {
    return !p.budgetDevice.empty() &&
           lower(glRenderer).find(lower(p.budgetDevice)) != std::string::npos;
}

std::string budgetOwnerText(const profile::PlatformProfile& p) {
    return "budget of " +
           (p.budgetDevice.empty() ? std::string("the target device") : p.budgetDevice);
}

double switchCostMs(const VariantResult& v) {
    if (!v.ok() || v.switchFrameSamples.empty() || v.frameSamples.empty()) return NAN;
    return stats::summarize(v.switchFrameSamples).median - v.frameMs.median;
}

std::string switchCostText(const VariantResult& v) {
    const double ms = switchCostMs(v);
    if (!std::isfinite(ms)) return "n/a";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.2f", ms);
    return buf;
}

} // namespace pb::bench
