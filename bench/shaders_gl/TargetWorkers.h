#pragma once
// The parent's side of `probebench shaders` (and `bench --targets`): one worker process per
// target - the same probebench, re-executed with the target's environment (MesaShim.h) and
// a worker command line the caller builds - whose JSON result is read back. A target that
// cannot run (driver not built, shim that does not load, a worker that fails or hangs) gets
// one line in `error`; the other targets are still collected.
#include "bench/shaders/MesaShim.h"
#include "bench/shaders/ShaderStatistics.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::shaders {

struct WorkerLaunch {
    // The worker's command without its output option: argv[0] is the executable path.
    std::vector<std::string> argv;
    std::string outOption = "--out"; // followed by the JSON file the worker writes
    int timeoutSeconds = 600;
};

std::vector<TargetStatistics>
collectOnTargets(const std::vector<ShaderTarget>& targets, const MesaShimInstall& install,
                 const WorkerLaunch& launch,
                 const std::function<void(const std::string&)>& progress);

// Whether the run found a problem the command must fail on: a target that did not run, or a
// program its driver rejected. One line per problem, naming the target.
std::vector<std::string> shaderRunProblems(const ShaderStatisticsRun& run);

} // namespace pb::shaders
