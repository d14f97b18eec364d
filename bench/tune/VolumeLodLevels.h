#pragma once
// The gi.volume_lod values `probebench tune` tries for a probe set: "all", each min_spacing:
// level that leaves out the volumes finer than one of the set's spacings, and - when the set
// has ranks (probes/store/VolumeRanksFile.h) - each rank_budget_mib: level of its drop order. Levels
// that keep the same volumes as an earlier one, or none, are left out. GL-free.
#include "probes/ProbeSet.h"

#include <string>
#include <vector>

namespace pb::bench {

std::vector<std::string> volumeLodLevels(const probes::ProbeSet& set);

} // namespace pb::bench
