#include "TargetWorkers.h"

#include "ChildProcess.h"
#include "core/Error.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace pb::shaders {
namespace {

namespace fs = std::filesystem;

// The last line of the worker's log that says what went wrong: probebench's own one-line error
// when there is one, else the last non-empty line (a loader's or driver's complaint).
std::string causeFromLog(const std::string& logFile) {
    std::ifstream in(logFile);
    std::string line, last, error;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        last = line;
        if (line.find("error: ") != std::string::npos) error = line;
    }
    const std::string& pick = error.empty() ? last : error;
    if (const size_t p = pick.find("error: "); p != std::string::npos) return pick.substr(p + 7);
    return pick.empty() ? "no output" : pick;
}

TargetStatistics collectOne(const ShaderTarget& target, const MesaShimInstall& install,
                            const WorkerLaunch& launch, const fs::path& dir) {
    TargetStatistics t;
    if (std::string why = targetUnavailableReason(target, install); !why.empty()) {
        t.error = why;
        return t;
    }
    const std::string out = (dir / (target.name + ".json")).string();
    const std::string log = (dir / (target.name + ".log")).string();
    std::vector<std::string> argv = launch.argv;
    argv.push_back(launch.outOption);
    argv.push_back(out);
    const ChildResult r =
        runChild(argv, targetEnvironment(target, install), log, launch.timeoutSeconds);
    if (r.timedOut) {
        t.error = "its worker did not finish within " + std::to_string(launch.timeoutSeconds) +
                  " s (a hanging shim?); log: " + causeFromLog(log);
        return t;
    }
    if (r.exitCode != 0 || !fs::exists(out)) {
        t.error =
            "its worker failed (exit " + std::to_string(r.exitCode) + "): " + causeFromLog(log);
        return t;
    }
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    try {
        t = targetStatisticsFromJson(nlohmann::json::parse(text.str()));
    } catch (const std::exception& e) {
        t = {};
        t.error = std::string("its worker wrote unreadable results: ") + e.what();
    }
    return t;
}

} // namespace

std::vector<TargetStatistics>
collectOnTargets(const std::vector<ShaderTarget>& targets, const MesaShimInstall& install,
                 const WorkerLaunch& launch,
                 const std::function<void(const std::string&)>& progress) {
    const fs::path dir =
        fs::temp_directory_path() / ("probebench-shaders-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw Error(dir.string() + ": cannot create the workers' folder");
    std::vector<TargetStatistics> out;
    for (const ShaderTarget& target : targets) {
        if (progress) progress(target.name + " (" + target.device + ")");
        const auto t0 = std::chrono::steady_clock::now();
        TargetStatistics t = collectOne(target, install, launch, dir);
        t.target = target.name;
        t.device = target.device;
        t.driver = target.driver;
        t.note = target.note;
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (progress)
            progress(target.name + ": " +
                     (t.error.empty() ? std::to_string(t.programs.size()) + " programs in " +
                                            std::to_string(int(s + 0.5)) + " s"
                                      : "not run: " + t.error));
        out.push_back(std::move(t));
    }
    fs::remove_all(dir, ec);
    return out;
}

std::vector<std::string> shaderRunProblems(const ShaderStatisticsRun& run) {
    std::vector<std::string> out;
    for (const TargetStatistics& t : run.targets) {
        if (!t.error.empty()) {
            out.push_back(t.target + ": " + t.error);
            continue;
        }
        for (const ProgramStatistics& p : t.programs) {
            if (!p.error.empty())
                out.push_back(t.target + ": " + p.vertex + "+" + p.fragment + " [" + p.defines +
                              "]: " + p.error);
            else if (!p.stage("fragment"))
                out.push_back(t.target + ": " + p.vertex + "+" + p.fragment +
                              ": the driver reported no fragment statistics");
        }
    }
    return out;
}

} // namespace pb::shaders
