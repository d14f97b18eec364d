// The sweep's internal commands, hidden from `probebench --help`; both engines run them the
// same way (bench/README.md "Sweeps"):
//   sweep-task --out DIR --task T   runs task T's jobs not yet finished cleanly, each as its
//                                   own probebench process, logs in DIR/logs, then its status
//                                   file (exit code, node, seconds) - written last, so a status
//                                   means the job's output is complete
//   sweep-merge --out DIR           the merge (SweepFinish.h); Slurm's dependent merge job
#include "CommandRegistry.h"
#include "bench/sweep/Subprocess.h"
#include "bench/sweep/SweepFinish.h"
#include "bench/gate_gl/WorkerProcess.h"
#include "bench/sweep/SweepState.h"
#include "core/Error.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace pb::app {
namespace {
namespace fs = std::filesystem;

std::string hostName() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}

int runTask(const std::string& outDir, std::size_t task) {
    const std::optional<sweep::PlanState> plan = sweep::readPlanState(outDir);
    if (!plan) throw Error("--out " + outDir + ": holds no sweep (no sweep-plan.json)");
    if (task >= plan->tasks())
        throw Error("--task: " + std::to_string(task) + " is not a task of this sweep (it has " +
                    std::to_string(plan->tasks()) + ")");
    const std::string self = gate::selfExecutable(), node = hostName();
    fs::create_directories(fs::path(outDir) / "logs");
    int failed = 0;
    for (std::size_t j = plan->firstJob(task); j < plan->endJob(task); ++j) {
        if (auto st = sweep::readJobStatus(outDir, j); st && st->exitCode == 0) continue;
        fs::remove(sweep::statusPath(outDir, j)); // an old failure is not this run's outcome
        const sweep::SweepJob& job = plan->jobs[j];
        fs::create_directories((fs::path(outDir) / job.output).parent_path());
        std::vector<std::string> argv{self};
        for (const std::string& a : sweep::substituteOut(job.args, outDir))
            argv.push_back(a);
        const auto t0 = std::chrono::steady_clock::now();
        const int pid = sweep::startLogged(argv, sweep::logPath(outDir, j, "out"),
                                    sweep::logPath(outDir, j, "err"));
        const int rc = sweep::waitFor(pid);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        sweep::writeJobStatus(outDir, {j, rc, node, seconds});
        std::cerr << "sweep-task: job " << j << " exit " << rc << " on " << node << " ("
                  << seconds << " s)\n";
        failed += rc != 0;
    }
    return failed == 0 ? 0 : 1;
}

struct TaskArgs {
    std::string out;
    std::size_t task = 0;
};

const RegisterCommand task{{
    "sweep-task",
    "Internal: run one task of a sweep (probebench sweep starts it)",
    901,
    [](CLI::App& cmd) -> std::function<int()> {
        cmd.group(""); // hidden from `probebench --help`
        auto a = std::make_shared<TaskArgs>();
        cmd.add_option("--out", a->out, "The sweep's output folder")->required();
        cmd.add_option("--task", a->task, "The task index")->required();
        return [a] { return runTask(sweep::canonicalDir(a->out), a->task); };
    },
}};

const RegisterCommand merge{{
    "sweep-merge",
    "Internal: merge a sweep's results (Slurm's merge job runs it)",
    902,
    [](CLI::App& cmd) -> std::function<int()> {
        cmd.group("");
        auto out = std::make_shared<std::string>();
        cmd.add_option("--out", *out, "The sweep's output folder")->required();
        return [out] {
            sweep::finishSweep(sweep::canonicalDir(*out));
            return 0;
        };
    },
}};

} // namespace
} // namespace pb::app
