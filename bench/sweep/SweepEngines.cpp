#include "SweepEngines.h"

#include "Subprocess.h"
#include "core/Error.h"

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <sys/wait.h>
#include <thread>

namespace pb::sweep {
namespace {
namespace fs = std::filesystem;

std::string taskLog(const std::string& outDir, const std::string& name) {
    return (fs::path(outDir) / "logs" / name).string();
}

std::size_t finishedJobs(const sweep::PlanState& plan, const std::string& outDir) {
    return plan.jobs.size() - sweep::unfinishedJobs(outDir, plan).size();
}

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' '))
        s.pop_back();
    return s;
}

// sbatch --parsable prints "JOBID" or "JOBID;CLUSTER".
std::string submit(const std::vector<std::string>& argv) {
    const Captured c = capture(argv);
    const std::string out = trim(c.output);
    const std::string id = out.substr(0, out.find(';'));
    if (c.exitCode != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw Error("--engine slurm: sbatch failed (exit " + std::to_string(c.exitCode) +
                    "): " + (out.empty() ? "no output" : out.substr(0, out.find('\n'))));
    return id;
}

} // namespace

void runLocal(const sweep::PlanState& plan, const std::vector<std::size_t>& tasks,
              const EngineOptions& o) {
    const std::size_t limit = std::size_t(o.maxParallel > 0 ? o.maxParallel : 1);
    fs::create_directories(fs::path(o.outDir) / "logs");
    std::map<int, std::size_t> running; // pid -> task
    std::size_t next = 0, ended = 0;
    while (ended < tasks.size()) {
        while (running.size() < limit && next < tasks.size()) {
            const std::size_t t = tasks[next++];
            const std::string tag = "task-" + std::to_string(t);
            running[startLogged({o.binary, "sweep-task", "--out", o.outDir, "--task",
                                 std::to_string(t)},
                                taskLog(o.outDir, tag + ".out"), taskLog(o.outDir, tag + ".err"))] =
                t;
        }
        // Waits for whichever task ends first (its pid is one of ours).
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR) continue;
            throw Error("sweep: lost track of the task processes");
        }
        const auto it = running.find(int(pid));
        if (it == running.end()) continue;
        running.erase(it);
        ++ended;
        std::cerr << "sweep: " << ended << " of " << tasks.size() << " task(s) ended, "
                  << finishedJobs(plan, o.outDir) << " of " << plan.jobs.size()
                  << " job(s) done\n";
    }
}

bool runSlurm(const sweep::PlanState& plan, const std::vector<std::size_t>& tasks,
              const EngineOptions& o) {
    if (capture({"sbatch", "--version"}).exitCode != 0)
        throw Error("--engine slurm: sbatch is not installed or does not run (Debian: "
                    "slurm-client; scripts/slurm-local.sh starts a one-node cluster)");
    fs::create_directories(fs::path(o.outDir) / "logs");
    const std::string out = shellQuote(o.outDir), bin = shellQuote(o.binary);
    std::vector<std::string> common{"sbatch", "--parsable", "--chdir=" + o.outDir};
    if (!o.partition.empty()) common.push_back("--partition=" + o.partition);

    std::vector<std::string> array = common;
    std::string range = "--array=" + sweep::indexRanges(tasks);
    if (o.maxParallel > 0) range += "%" + std::to_string(o.maxParallel);
    for (const std::string& a :
         {"--job-name=pb-sweep-" + plan.name, range,
          "--output=" + taskLog(o.outDir, "task-%a.out"),
          "--error=" + taskLog(o.outDir, "task-%a.err"), std::string("--wrap"),
          "exec " + bin + " sweep-task --out " + out + " --task \"$SLURM_ARRAY_TASK_ID\""})
        array.push_back(a);
    const std::string arrayId = submit(array);

    std::vector<std::string> merge = common;
    for (const std::string& a :
         {"--job-name=pb-sweep-" + plan.name + "-merge", "--dependency=afterok:" + arrayId,
          std::string("--kill-on-invalid-dep=yes"), "--output=" + taskLog(o.outDir, "merge.out"),
          "--error=" + taskLog(o.outDir, "merge.err"), std::string("--wrap"),
          "exec " + bin + " sweep-merge --out " + out})
        merge.push_back(a);
    const std::string mergeId = submit(merge);
    std::cerr << "sweep: submitted job array " << arrayId << " (" << tasks.size()
              << " task(s): " << sweep::indexRanges(tasks) << ") and merge job " << mergeId
              << "\n";

    // Follows both jobs in squeue until neither is queued or running.
    std::string last;
    for (;;) {
        const Captured q = capture({"squeue", "-h", "-j", arrayId + "," + mergeId, "-o", "%i %T"});
        if (q.exitCode != 0 && q.output.find("Invalid job id") == std::string::npos)
            throw Error("--engine slurm: squeue failed: " + trim(q.output));
        std::size_t running = 0, pending = 0;
        bool mergeQueued = false, arrayQueued = false;
        std::istringstream lines(q.exitCode == 0 ? q.output : "");
        for (std::string id, state; lines >> id >> state;) {
            const bool isMerge = id == mergeId;
            mergeQueued = mergeQueued || isMerge;
            arrayQueued = arrayQueued || !isMerge;
            if (isMerge) continue;
            (state == "RUNNING" || state == "COMPLETING" ? running : pending) += 1;
        }
        std::ostringstream now;
        now << "sweep: array " << arrayId << ": " << running << " running, " << pending
            << " pending; " << finishedJobs(plan, o.outDir) << " of " << plan.jobs.size()
            << " job(s) done; merge " << (mergeQueued ? "queued" : "not queued");
        if (now.str() != last) std::cerr << now.str() << "\n";
        last = now.str();
        if (!mergeQueued && !arrayQueued) break;
        // A failed task makes the merge's dependency impossible: Slurm cancels it
        // (--kill-on-invalid-dep); this cancels it too where that is configured off.
        if (!arrayQueued && mergeQueued && !sweep::unfinishedJobs(o.outDir, plan).empty())
            capture({"scancel", mergeId});
        std::this_thread::sleep_for(std::chrono::duration<double>(o.pollSeconds));
    }
    return fs::exists(taskLog(o.outDir, "merge.out")) &&
           sweep::unfinishedJobs(o.outDir, plan).empty();
}

} // namespace pb::sweep
