#include "core/MachineState.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace pb {
namespace {

std::string firstLine(const char* path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

std::string percent(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", share * 100.0);
    return buf;
}

} // namespace

MachineState sampleMachineState() {
    MachineState m;
    std::istringstream load(firstLine("/proc/loadavg"));
    load >> m.loadAverage;
    std::istringstream stat(firstLine("/proc/stat"));
    std::string cpu;
    stat >> cpu;
    std::uint64_t field = 0;
    for (int i = 0; stat >> field; ++i) {
        m.totalTicks += i < 8 ? field : 0;          // guest time is already counted in user time
        if (i == 3 || i == 4) m.idleTicks += field; // idle, iowait
        if (i == 7) m.stealTicks = field;
    }
    // /proc/self/stat: fields 14 and 15 (utime, stime) after the command name in parentheses.
    const std::string self = firstLine("/proc/self/stat");
    std::istringstream rest(self.substr(std::min(self.size(), self.rfind(')') + 1)));
    std::string f;
    for (int i = 3; i <= 15 && rest >> f; ++i)
        if (i == 14 || i == 15) m.ownTicks += std::strtoull(f.c_str(), nullptr, 10);
    m.valid = cpu == "cpu" && load && m.totalTicks > 0;
    m.cpus = int(std::thread::hardware_concurrency());
    m.governor = firstLine("/sys/devices/system/cpu/cpu0/cpufreq/scaling_governor");
    return m;
}

double stealShare(const MachineState& before, const MachineState& after) {
    if (!before.valid || !after.valid || after.totalTicks <= before.totalTicks) return -1;
    return double(after.stealTicks - before.stealTicks) /
           double(after.totalTicks - before.totalTicks);
}

double otherBusyCpus(const MachineState& before, const MachineState& after) {
    if (!before.valid || !after.valid || after.totalTicks <= before.totalTicks) return -1;
    const double total = double(after.totalTicks - before.totalTicks);
    const double busy = total - double(after.idleTicks - before.idleTicks) -
                        double(after.stealTicks - before.stealTicks);
    const double own = double(after.ownTicks - before.ownTicks);
    return std::max(0.0, (busy - own) / total * std::max(after.cpus, 1));
}

std::string noisyMachineText(const MachineState& before, const MachineState& after) {
    std::string out;
    const double others = otherBusyCpus(before, after);
    const int cpus = std::max(before.cpus, after.cpus);
    if (cpus > 0 && others > cpus / 2.0) {
        char buf[128];
        std::snprintf(buf, sizeof buf,
                      "other processes kept %.1f of %d CPUs busy (load average %.2f)", others, cpus,
                      std::max(before.loadAverage, after.loadAverage));
        out = buf;
    }
    const double steal = stealShare(before, after);
    if (steal > kQuietStealShare)
        out += (out.empty() ? "" : ", ") + percent(steal) + " of the CPU time stolen by the host";
    return out;
}

std::string noisyMachineNow(double seconds) {
    const MachineState before = sampleMachineState();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const MachineState after = sampleMachineState();
    std::string out = noisyMachineText(before, after);
    const int cpus = std::max(after.cpus, 1);
    if (out.empty() && after.loadAverage > cpus / 2.0) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "load average %.2f on %d CPUs (more than half busy)",
                      after.loadAverage, cpus);
        out = buf;
    }
    return out;
}

nlohmann::json toJson(const MachineState& before, const MachineState& after) {
    const double steal = stealShare(before, after);
    const double others = otherBusyCpus(before, after);
    return {
        {"load_average_before", before.loadAverage},
        {"load_average_after", after.loadAverage},
        {"cpu_steal_share", steal >= 0 ? nlohmann::json(steal) : nlohmann::json()},
        {"other_busy_cpus", others >= 0 ? nlohmann::json(others) : nlohmann::json()},
        {"cpus", std::max(before.cpus, after.cpus)},
        {"governor", after.governor.empty() ? nlohmann::json() : nlohmann::json(after.governor)},
        {"quiet", noisyMachineText(before, after).empty()}};
}

} // namespace pb
