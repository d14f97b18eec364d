#pragma once
// `bench --truth`'s "one fewer bounce pass" (issue 43): what convergence buys. The bench's
// probes are baked again from the request they were baked from (RebuiltRequest.h: same
// volumes, rays, seed, storage) with one bounce pass fewer than they ran, and the reference
// profile renders with them against the same truth (SessionRunner.h). Later passes trace only
// the light the pass before added, so this set is the probes' own sum without its last pass.
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace pb::bench {

struct FewerBouncePasses {
    int passes = 0;                      // the probes' bounce passes (their first scenario's)
    std::optional<probes::ProbeSet> set; // baked with passes - 1; empty: see `why`
    std::string why;
    double seconds = 0.0; // the bakes this took (a converged set is baked once more to count)
};

// A converged set (bounces 0) does not record how many passes it ran: `knownPasses` (> 0) when
// the caller baked it, else it is baked once more (its first scenario only) to count them.
// `progress` gets a line per bake. Never throws for probes it cannot rebuild: `why` says so (a
// bake error still throws pb::Error).
FewerBouncePasses bakeOneFewerBouncePass(const scene::Scene& s, const probes::ProbeSet& set,
                                         int knownPasses,
                                         const std::function<void(const std::string&)>& progress);

// What the JSON's truth.fewer_bounce_passes shows: passes, the baked passes, seconds or why not.
nlohmann::json fewerBouncePassesJson(const FewerBouncePasses& f);

} // namespace pb::bench
