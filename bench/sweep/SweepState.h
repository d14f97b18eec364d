#pragma once
// What a sweep keeps in its output folder, so any engine, any node and a later --resume see
// the same state (bench/README.md "Sweeps" lists the layout):
//   sweep-plan.json      the expanded plan: name, id, node class, chunk, jobs
//   status/NNNN.json     one per finished job: exit code, node, seconds (written last)
//   logs/NNNN.out|.err   the job's stdout and stderr
//   jobs/, bakes/, cache/ the jobs' own outputs
// A task (one Slurm array index, one local worker) runs `chunk` consecutive jobs.
#include "SweepPlan.h"

#include <optional>
#include <string>
#include <vector>

namespace pb::sweep {

struct PlanState {
    std::string name, nodeClass, id;
    std::size_t chunk = 1;
    std::vector<SweepJob> jobs;

    std::size_t tasks() const { return (jobs.size() + chunk - 1) / chunk; }
    std::size_t firstJob(std::size_t task) const { return task * chunk; }
    std::size_t endJob(std::size_t task) const { return std::min(jobs.size(), (task + 1) * chunk); }
};

struct JobStatus {
    std::size_t index = 0;
    int exitCode = -1;
    std::string node;
    double seconds = 0.0;
};

// `dir` absolute and normal, without a trailing slash: how every sweep command names its
// output folder (job arguments, the merge's relative paths).
std::string canonicalDir(const std::string& dir);

std::string planStatePath(const std::string& outDir);
std::string statusPath(const std::string& outDir, std::size_t job);
std::string logPath(const std::string& outDir, std::size_t job, const char* stream); // out|err

void writePlanState(const std::string& outDir, const PlanState& s);
// Nothing when the folder holds no plan; throws pb::Error naming the file when it is corrupt.
std::optional<PlanState> readPlanState(const std::string& outDir);

void writeJobStatus(const std::string& outDir, const JobStatus& s);
// Nothing when the job has not finished (or its status is unreadable: it then runs again).
std::optional<JobStatus> readJobStatus(const std::string& outDir, std::size_t job);

// Jobs with no status or a non-zero exit code.
std::vector<std::size_t> unfinishedJobs(const std::string& outDir, const PlanState& s);
// Tasks holding at least one unfinished job: what --resume submits again.
std::vector<std::size_t> unfinishedTasks(const std::string& outDir, const PlanState& s);

// "0-3,7,9-10": a Slurm --array index list.
std::string indexRanges(const std::vector<std::size_t>& indices);

// The last `lines` lines of a text file (empty when it is missing).
std::string tailOfFile(const std::string& path, std::size_t lines);

} // namespace pb::sweep
