#pragma once
// Splits the bake's tracing time into named phases (BakeStats::phases, reported by bench_bake),
// wall clock and CPU seconds of the whole process, summed per name over the passes.
#include "probes/bake/Baker.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace pb::probes {

class BakePhaseClock {
public:
    BakePhaseClock() : wall_(Clock::now()), cpu_(processCpuSeconds()) {}

    // Charges the time since the previous mark (or construction) to `name`.
    void mark(const char* name) {
        const auto wall = Clock::now();
        const double cpu = processCpuSeconds();
        auto it = std::find_if(phases_.begin(), phases_.end(),
                               [&](const BakePhase& p) { return p.name == name; });
        if (it == phases_.end()) it = phases_.insert(phases_.end(), BakePhase{name});
        it->wallSeconds += std::chrono::duration<double>(wall - wall_).count();
        it->cpuSeconds += cpu - cpu_;
        wall_ = wall;
        cpu_ = cpu;
    }
    std::vector<BakePhase> take() { return std::move(phases_); }

    static double processCpuSeconds() {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
    }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point wall_;
    double cpu_;
    std::vector<BakePhase> phases_;
};

} // namespace pb::probes
