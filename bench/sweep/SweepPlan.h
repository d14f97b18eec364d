#pragma once
// A sweep plan (bench/sweeps/*.toml, bench/README.md "Sweeps") and its expansion into jobs:
// each job one self-contained `probebench` command line with its own output file, so any
// machine that sees the output folder can run any job, in any order. The expansion is
// deterministic: the same plan gives the same jobs in the same order, and the plan's id
// (a hash of the jobs) tells one plan's results from another's in an output folder.
//
// Job arguments name the output folder as "{out}"; the task that runs a job substitutes it
// (so the id does not depend on where the folder is mounted).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pb::sweep {

inline constexpr const char* kOutPlaceholder = "{out}";

struct BenchAxes {
    std::vector<std::string> scenes, profiles, resolutions; // resolutions "WxH"
    std::vector<std::vector<std::string>> switchSets;       // each: --set k=v; empty: none
    int repeat = 1;
    std::vector<std::string> args; // added to every bench job
};

// A split bake per scene: `bake --split scenario --part I/N`, joined by bake-merge.
struct BakeAxes {
    std::vector<std::string> scenes, scenarios;
    int parts = 0; // 0: one part per scenario
    std::vector<std::string> args;
};

// Any other probebench command (a stress case, a tune slice): `args` verbatim, plus
// `output_option` (e.g. "--json") naming the job's own output file.
struct CommandJob {
    std::string name;
    std::vector<std::string> args;
    std::string outputOption;
};

struct SweepPlan {
    std::string name;
    // Set when every node that runs the plan is one class of machine (same CPU and device):
    // only then are timings of different nodes put side by side.
    std::string nodeClass;
    std::vector<BenchAxes> bench;
    std::vector<BakeAxes> bake;
    std::vector<CommandJob> commands;
};

struct SweepJob {
    std::size_t index = 0;
    std::string kind;              // "bench", "bake-part", "command"
    std::vector<std::string> args; // after the binary; "{out}" is the output folder
    std::string output;            // the job's output file, relative to the output folder
    nlohmann::json labels;         // what the job varies (scene, profile, resolution, part...)
};

// A split bake's parts and the file bake-merge writes from them.
struct BakeGroup {
    std::string scene;
    std::vector<std::size_t> jobs; // its part jobs, part 0 first
    std::string merged;            // relative to the output folder
};

// Throws pb::Error "path:LINE: problem" (unknown keys included) or "path: problem".
SweepPlan loadSweepPlan(const std::string& path);
SweepPlan parseSweepPlan(const std::string& text, const std::string& path);

// Throws pb::Error "path: the plan expands to no jobs" for an empty plan.
std::vector<SweepJob> expandSweepPlan(const SweepPlan& plan, const std::string& path);
std::vector<BakeGroup> bakeGroups(const std::vector<SweepJob>& jobs);

// A job's number as the sweep folder's file names spell it: 4 digits at least ("0007"), in
// jobs/, bakes/, status/ and logs/ alike.
std::string jobNumberText(std::size_t job);

// FNV-1a of the jobs' kinds, arguments and outputs, as 16 hex digits.
std::string planId(const std::vector<SweepJob>& jobs);

// "{out}" -> `outDir` in every argument.
std::vector<std::string> substituteOut(const std::vector<std::string>& args,
                                       const std::string& outDir);

nlohmann::json jobJson(const SweepJob& j);
SweepJob jobFromJson(const nlohmann::json& j);

} // namespace pb::sweep
