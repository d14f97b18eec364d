#pragma once
// What a baked probe set holds, per volume and in all, as the bake summary reports it: stored
// probes, absent ones (sparse storage left them out: no surface nearby, SparseStorage.h) and
// invalid ones (inside geometry, as the bake classified them; sparse storage stores none).
// Since probe file version 7 an absent probe keeps its irradiance (ProbeState::irradianceOnly,
// valid), so the states tell it from an invalid one. Before, an absent probe was invalid in
// memory and in the file: the split then needs the bake's own count of invalid probes
// (BakeStats::invalidPerVolume), and an older sparse file read back cannot be split.
#include "probes/ProbeSet.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace pb::probes {

struct ProbeCounts {
    std::size_t probes = 0, stored = 0;
    // Unknown (nullopt) only for a volume with probes not stored and no bake counts.
    std::optional<std::size_t> absent, invalid;
    std::size_t notStored() const { return probes - stored; }
};

// One entry per volume of `set`. `bakedInvalid`: per volume, the probes the bake found invalid
// before sparse storage (BakeStats::invalidPerVolume), or null when not known (a file read
// back). Throws pb::Error when its size does not match the volumes or its counts the states.
std::vector<ProbeCounts> volumeProbeCounts(const ProbeSet& set,
                                           const std::vector<std::size_t>* bakedInvalid);
// The sum; absent and invalid unknown when any volume's are.
ProbeCounts totalProbeCounts(const std::vector<ProbeCounts>& volumes);

} // namespace pb::probes
