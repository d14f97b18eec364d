#pragma once
// The state of the machine a timing ran on, taken before and after it: load average, CPU time
// stolen by the hypervisor (from /proc/stat) and the CPU frequency governor. A shared runner's
// timings are only as good as its quietest moment; the bench and the gate record this per
// session, warn in their reports when it was noisy, and refuse to time with --require-quiet.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace pb {

struct MachineState {
    bool valid = false;      // /proc was readable
    double loadAverage = -1; // 1-minute load average (/proc/loadavg)
    // Cumulative ticks of all CPUs (/proc/stat's "cpu" line) and of this process (its user +
    // system time, /proc/self/stat), in the same clock ticks.
    std::uint64_t totalTicks = 0, idleTicks = 0, stealTicks = 0, ownTicks = 0;
    int cpus = 0;         // online CPUs
    std::string governor; // cpu0's scaling_governor; "" without cpufreq (most VMs)
};

MachineState sampleMachineState();

// Share of CPU time stolen by the host between two samples (0..1); -1 when unknown.
double stealShare(const MachineState& before, const MachineState& after);

// CPUs kept busy by other processes between two samples (busy time less this process's,
// in CPUs); -1 when unknown. The load average cannot say it: a bench on llvmpipe keeps every
// core busy itself.
double otherBusyCpus(const MachineState& before, const MachineState& after);

// Other processes busy on more than half the CPUs, or more than 5% of the time stolen: the
// machine was not quiet.
inline constexpr double kQuietStealShare = 0.05;
// One line naming the figures ("other processes kept 1.6 of 2 CPUs busy (load average 5.28),
// 7.1% of the CPU time stolen by the host"), or "" when it was quiet over [before, after].
std::string noisyMachineText(const MachineState& before, const MachineState& after);

// The machine right now, over `seconds` of this process sleeping (for --require-quiet):
// "" when quiet (load average and others' CPU use at most half the CPUs, steal at most 5%),
// else the same line as noisyMachineText.
std::string noisyMachineNow(double seconds = 1.0);

nlohmann::json toJson(const MachineState& before, const MachineState& after);

} // namespace pb
