#pragma once
// `probebench bake`'s report of the probes it obtained (ObtainProbes.h): the JSON of --json and
// the lines for people, from one set of figures - counts (stored, absent, invalid, relocated),
// rays and noise, the time by phase, quantisation, storage scales, memory, sparse storage and
// free space. cmd_bake.cpp only prints them; as bench/report is to `bench`.
#include "probes/ProbeSet.h"
#include "probes/bake/Baker.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::probes {

// Wall seconds of the whole command, by phase (issue 17: the summary's time once covered only
// the tracing). The bake's own are BakeStats::seconds (BVH, tracing, encoding).
struct CommandSeconds {
    double command = 0.0, load = 0.0, placement = 0.0, write = 0.0;
};

struct BakeReport {
    std::string file;           // the probe file
    nlohmann::json placement;   // PlacementSummary.h's JSON (this run's or the cache's)
    bool placedThisRun = true;
    bool upToDate = false;      // the file was reused, nothing baked
    const ProbeSet& set;
    const BakeStats* stats = nullptr; // only when baked
    std::size_t freeSpace = 0;  // freeSpaceProbes(set, scene)
    CommandSeconds times;
};

// The stored probes only the free-space lattice keeps (the cost of lighting the air between
// surfaces, issue 18); a dense set has none and is not classified against the scene's
// triangles, so an up-to-date run stays quick.
std::size_t freeSpaceProbes(const ProbeSet& set, const scene::Scene& s);

// "placement: adaptive, 5 volume(s); outer 1 x spacing ...": one line from the placement's JSON,
// so a cached placement prints as a fresh one does.
std::string placementText(const nlohmann::json& placement, bool placedThisRun);

// `bake --json`: the same figures as the text, about 45 keys.
nlohmann::json bakeReportJson(const BakeReport& r);

// The summary lines, each ending in a newline; "wrote FILE" last when something was written.
std::string bakeReportText(const BakeReport& r);

// One line (no "warning: ", no newline) when probes stayed above the noise target after the
// round cap: how many, their share, where most of them are and what to do; "" otherwise.
std::string noiseTargetWarning(const BakeReport& r);

} // namespace pb::probes
