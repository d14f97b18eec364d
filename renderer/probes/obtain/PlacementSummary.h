#pragma once
// What a placement chose, as JSON: the mode, per nesting tier the volumes, probes and spacing,
// the stored bytes against the budget, the lattice search and the adaptive placement's counts.
// `bake` prints it (one line) and puts it in --json; the placement cache (PlacementCache.h)
// keeps it, so an up-to-date probe file reports the placement it was baked with.
#include "probes/StorageFormat.h"
#include "probes/placement/AutoPlacement.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::probes {

struct PlacementInfo {
    std::string mode;    // "adaptive", "uniform" or "file"
    bool sparse = false; // stored sparse: result.bytes counts what is stored
    AutoPlacementResult result;
};

nlohmann::json placementJson(const PlacementInfo& p, StorageFormat format);

} // namespace pb::probes
