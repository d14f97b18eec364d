#pragma once
// The merge every sweep ends in, on whichever engine (the local process, or Slurm's merge job
// through `probebench sweep-merge`): split bakes joined by bake-merge's code, then the jobs'
// results into DIR/sweep.json, DIR/report.html and DIR/summary.md (bench/sweep/SweepMerge.h).
#include <string>

namespace pb::sweep {

inline constexpr const char* kSweepJson = "sweep.json";
inline constexpr const char* kSweepHtml = "report.html";
inline constexpr const char* kSweepMarkdown = "summary.md";

// Throws pb::Error when a job has not finished cleanly or an output is missing or damaged.
void finishSweep(const std::string& outDir);

} // namespace pb::sweep
