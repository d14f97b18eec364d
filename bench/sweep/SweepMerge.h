#pragma once
// The end of every sweep, whichever engine ran it: the jobs' outputs joined into one JSON
// (schema probebench.sweep/1, a superset of `bench --json`: its profiles[] and variants[]
// entries are the bench jobs' own, each with "job", "node" and the job's labels added), a
// Markdown summary and a self-contained HTML report. Timings are grouped by node: medians of
// different machines are put side by side only when the plan names one node class.
#include "SweepState.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::sweep {

// Reads every job's status and output (bench and command jobs: their JSON) from `outDir`.
// `bakes` is what the caller's bake-merge made of the bake groups (scene, file, bytes, hash).
// Paths under `outDir` inside the results are made relative to it. Throws pb::Error naming
// a job's output when it is missing or not JSON.
nlohmann::json mergeSweep(const PlanState& plan, const std::string& outDir,
                          const nlohmann::json& bakes);

// The merged result without what depends on the machine's speed or load: contexts, nodes,
// seconds and every timing (keys "ms", "*_ms", and the figures derived from them). Two runs
// of one plan, on any engine, give equal results after this.
nlohmann::json withoutTimings(const nlohmann::json& j);

std::string sweepMarkdown(const nlohmann::json& merged);
std::string sweepHtml(const nlohmann::json& merged);

} // namespace pb::sweep
