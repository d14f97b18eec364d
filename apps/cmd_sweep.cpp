// probebench sweep: a plan (bench/sweeps/*.toml) expanded into self-contained probebench jobs,
// run here (--engine local) or as a Slurm job array (--engine slurm), merged into one JSON,
// HTML report and Markdown summary (bench/README.md "Sweeps"; bench/sweep/ holds the GL-free
// plan, state and merge, SweepEngines.h the two engines).
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "bench/sweep/SweepEngines.h"
#include "bench/sweep/SweepFinish.h"
#include "bench/gate_gl/WorkerProcess.h"
#include "bench/sweep/SweepPlan.h"
#include "bench/sweep/SweepState.h"
#include "core/Error.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pb::app {
namespace {
namespace fs = std::filesystem;

struct SweepArgs {
    std::string plan, engine = "local", out, partition, binary;
    int maxParallel = 0, chunk = 1;
    double pollSeconds = 2.0;
    bool mkdir = false; // --mkdir: create --out's parent folder
    bool resume = false;
};

// The output folder must be new, empty, or hold this very plan (then only with --resume).
// Decided before anything is submitted or run.
sweep::PlanState prepareFolder(const SweepArgs& a, const std::string& dir,
                               sweep::PlanState fresh) {
    std::error_code ec;
    const std::optional<sweep::PlanState> old = sweep::readPlanState(dir);
    if (old && old->id != fresh.id)
        throw Error("--out " + dir + ": holds the results of another plan ('" + old->name +
                    "', plan id " + old->id + "; this plan is '" + fresh.name + "', " + fresh.id +
                    "); use another folder");
    if (old && !a.resume)
        throw Error("--out " + dir + ": already holds this plan's results (" +
                    std::to_string(old->jobs.size() - sweep::unfinishedJobs(dir, *old).size()) +
                    " of " + std::to_string(old->jobs.size()) +
                    " jobs finished); --resume runs the unfinished ones again");
    if (!old && a.resume) throw Error("--resume: " + dir + " holds no sweep to resume");
    if (!old && fs::exists(dir) && !fs::is_empty(dir, ec))
        throw Error("--out " + dir + ": is not empty and holds no sweep; use a new or empty "
                    "folder");
    if (old) {
        if (old->chunk != fresh.chunk)
            std::cerr << "note: --resume keeps the sweep's --chunk " << old->chunk << "\n";
        return *old;
    }
    fs::create_directories(dir, ec);
    if (ec) throw Error("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
    sweep::writePlanState(dir, fresh);
    return fresh;
}

std::string indented(const std::string& text) {
    std::istringstream lines(text);
    std::string out;
    for (std::string line; std::getline(lines, line);)
        out += "    " + line + "\n";
    return out;
}

// Every job that did not finish cleanly, with its stderr's last lines.
std::string failureReport(const sweep::PlanState& plan, const std::string& dir) {
    std::ostringstream s;
    for (std::size_t j : sweep::unfinishedJobs(dir, plan)) {
        const std::optional<sweep::JobStatus> st = sweep::readJobStatus(dir, j);
        const std::size_t task = j / plan.chunk;
        if (st) {
            s << "job " << j << " (task " << task << ") failed: exit " << st->exitCode << " on "
              << st->node << "; stderr " << sweep::logPath(dir, j, "err") << " ends:\n";
            s << indented(sweep::tailOfFile(sweep::logPath(dir, j, "err"), 5));
        } else {
            const std::string log =
                (fs::path(dir) / "logs" / ("task-" + std::to_string(task) + ".err")).string();
            s << "job " << j << " (task " << task << ") did not run to its end; " << log
              << " ends:\n";
            s << indented(sweep::tailOfFile(log, 5));
        }
    }
    return s.str();
}

int runSweep(const SweepArgs& a) {
    if (a.engine != "local" && a.engine != "slurm")
        throw UsageError("--engine: expected local or slurm (got '" + a.engine + "')");
    if (a.maxParallel < 0) throw UsageError("--max-parallel: must be 1 or more");
    if (a.chunk < 1) throw UsageError("--chunk: must be 1 or more");
    if (!(a.pollSeconds > 0.0 && a.pollSeconds <= 600.0))
        throw UsageError("--poll-seconds: must be in (0, 600]");
    if (!a.partition.empty() && a.engine != "slurm")
        throw Error("--partition: applies to --engine slurm only");
    checkOutputFolder("--out", a.out, a.mkdir); // OutputPaths.h: before any job runs
    const sweep::SweepPlan plan = sweep::loadSweepPlan(a.plan);
    sweep::PlanState fresh;
    fresh.name = plan.name;
    fresh.nodeClass = plan.nodeClass;
    fresh.chunk = std::size_t(a.chunk);
    fresh.jobs = sweep::expandSweepPlan(plan, a.plan);
    fresh.id = sweep::planId(fresh.jobs);
    const std::string dir = sweep::canonicalDir(a.out);
    const sweep::PlanState state = prepareFolder(a, dir, fresh);

    for (const char* f : {sweep::kSweepJson, sweep::kSweepHtml, sweep::kSweepMarkdown})
        fs::remove(fs::path(dir) / f); // a merged result always belongs to this run
    const std::vector<std::size_t> tasks = sweep::unfinishedTasks(dir, state);
    std::cerr << "sweep: plan '" << state.name << "' (" << state.id << "): "
              << state.jobs.size() << " job(s) in " << state.tasks() << " task(s), "
              << tasks.size() << " to run, engine " << a.engine << "\n";

    sweep::EngineOptions o;
    o.outDir = dir;
    o.binary = a.binary.empty() ? gate::selfExecutable() : a.binary;
    o.maxParallel = a.maxParallel;
    o.partition = a.partition;
    o.pollSeconds = a.pollSeconds;
    bool merged = false;
    if (!tasks.empty()) {
        if (a.engine == "local")
            sweep::runLocal(state, tasks, o);
        else
            merged = sweep::runSlurm(state, tasks, o);
    }
    if (!sweep::unfinishedJobs(dir, state).empty()) {
        std::cerr << failureReport(state, dir);
        throw Error("sweep: " + std::to_string(sweep::unfinishedJobs(dir, state).size()) +
                    " of " + std::to_string(state.jobs.size()) +
                    " job(s) failed; the others' results are kept in " + dir +
                    "; --resume runs only the failed ones again");
    }
    // The local engine merges here; Slurm's merge job did (an empty resume merges here too).
    if (a.engine == "local" || tasks.empty()) sweep::finishSweep(dir);
    if (!fs::exists(fs::path(dir) / sweep::kSweepJson))
        throw Error("sweep: the merge job wrote no " + std::string(sweep::kSweepJson) + " (merged " +
                    (merged ? "" : "not ") + "run; see " + dir + "/logs/merge.err)");
    std::ifstream md(fs::path(dir) / sweep::kSweepMarkdown);
    std::cout << md.rdbuf();
    std::cout << "\nwrote " << dir << "/" << sweep::kSweepJson << ", " << sweep::kSweepHtml << ", "
              << sweep::kSweepMarkdown << "\n";
    return 0;
}

const RegisterCommand registerSweep{{
    "sweep",
    "Run a sweep plan's jobs here or as a Slurm job array, merged into one result",
    85,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<SweepArgs>();
        cmd.footer("A plan (bench/sweeps/*.toml) expands to jobs, each one probebench command "
                   "line with its own output file in --out. Both engines end in one merge: "
                   "DIR/sweep.json (a superset of bench --json), DIR/report.html and "
                   "DIR/summary.md, with timings grouped by node. bench/README.md, \"Sweeps\".");
        cmd.add_option("--plan", a->plan, "The sweep plan (TOML)")->required();
        cmd.add_option("--engine", a->engine,
                       "local: run the tasks on this machine; slurm: one sbatch job array plus "
                       "a merge job that depends on it")
            ->capture_default_str();
        cmd.add_option("--out", a->out,
                       "The output folder: new or empty, or this plan's with --resume (on a "
                       "cluster: a shared filesystem path every node sees)")
            ->required();
        cmd.add_flag("--mkdir", a->mkdir, "Create the missing parent folder of --out (else a missing folder is an error, before any work)");
        cmd.add_option("--partition", a->partition, "Slurm partition (default: the cluster's)");
        cmd.add_option("--max-parallel", a->maxParallel,
                       "Tasks running at once (local default 1; slurm: the array's %M, default "
                       "no limit)");
        cmd.add_option("--chunk", a->chunk, "Jobs per task (one array index runs this many)")
            ->capture_default_str();
        cmd.add_flag("--resume", a->resume,
                     "Run only the jobs of --out that failed or never ran, then merge");
        cmd.add_option("--binary", a->binary,
                       "probebench as the nodes see it (default: this binary's path; it must be "
                       "on a filesystem the nodes share)");
        cmd.add_option("--poll-seconds", a->pollSeconds, "How often squeue is asked (slurm)")
            ->capture_default_str();
        return [a] { return runSweep(*a); };
    },
}};

} // namespace
} // namespace pb::app
