#pragma once
// The two ways `probebench sweep` runs a plan's tasks (bench/README.md "Sweeps"). Both start
// `probebench sweep-task --out DIR --task T` per task (cmd_sweep_worker.cpp), so a job runs
// the same way on either; they differ only in who starts the tasks and where.
#include "bench/sweep/SweepState.h"

#include <string>
#include <vector>

namespace pb::sweep {

struct EngineOptions {
    std::string outDir;  // canonical (SweepState.h)
    std::string binary;  // probebench as the tasks' machines see it
    int maxParallel = 0; // 0: local 1, Slurm no limit
    std::string partition;
    double pollSeconds = 2.0;
};

// Runs `tasks` on this machine, up to maxParallel at a time; returns when all have ended.
void runLocal(const sweep::PlanState& plan, const std::vector<std::size_t>& tasks,
              const EngineOptions& o);

// Submits `tasks` as one Slurm job array (`sbatch --array=...%M`) and a merge job that depends
// on it (`--dependency=afterok`, cancelled by Slurm when a task fails), then follows them with
// squeue until both have left the queue. Returns whether the merge job ran (it writes the
// merged results); throws pb::Error when sbatch refuses.
bool runSlurm(const sweep::PlanState& plan, const std::vector<std::size_t>& tasks,
              const EngineOptions& o);

} // namespace pb::sweep
