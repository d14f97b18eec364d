#pragma once
// What a baked probe set holds, per volume and in all, as the bake summary reports it: stored
// probes, absent ones (sparse storage left them out: no surface nearby, SparseStorage.h) and
// invalid ones (inside geometry, as the bake classified them; sparse storage stores none).
// The bake knows its invalid count (BakeStats::invalidPerVolume). A set read back from a file
// tells them apart by the states, as lookups do: a probe not stored is absent when it keeps its
// irradiance (ProbeState::irradianceOnly) or its back-face ratio puts it outside geometry (a
// stand-in is read for it, AbsentProbeFill.h), and invalid otherwise.
#include "probes/ProbeSet.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace pb::probes {

struct ProbeCounts {
    std::size_t probes = 0, stored = 0;
    // Always set by volumeProbeCounts; unknown (nullopt) in a total over unknown counts.
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
