#pragma once
// The placement cache of every probe file ObtainProbes.h writes (bake's --out, the bench's
// cache): FILE.placement.json beside the probe file FILE records the
// automatic placement's key (probes/placement/PlacementKey.h), the input hash of the bake it
// led to and the placement's summary. A re-run whose key matches takes the volumes from the
// probe file and checks the bake's own hash against them, so "up to date" is printed without
// placing or searching the lattice again (issue 25, item 10: a re-run took 8.9 s for it).
// Nothing is trusted blindly: a missing, unreadable or mismatched sidecar just means placing.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace pb::probes {

struct CachedPlacement {
    std::uint64_t placementKey = 0;
    std::uint64_t inputHash = 0; // the bake's (ProbeSet::inputHash) that this placement led to
    nlohmann::json placement;    // the summary `bake` prints and puts in --json
};

std::string placementCachePath(const std::string& probeFile);

// The sidecar of `probeFile` when it exists, parses and has `placementKey`; otherwise nothing.
std::optional<CachedPlacement> readPlacementCache(const std::string& probeFile,
                                                  std::uint64_t placementKey);

// Written atomically; a failure to write it is not the bake's failure (a note on stderr).
void writePlacementCache(const std::string& probeFile, const CachedPlacement& cached);

} // namespace pb::probes
