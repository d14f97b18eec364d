#pragma once
// The volume-ranks sidecar of a probe file: FILE.ranks.json next to FILE, written by
// `probebench volumes --rank --write-ranks`. A sidecar rather than a section of the probe file:
// ranks depend on views and a scene the probe file does not hold, they are re-measured without
// re-baking, and the binary format (and its readers and fuzzers) stays as it is. It names the
// probe set's input hash and every volume in file order; a sidecar that does not match the set
// is never used (re-rank after a re-bake). GL-free.
#include "probes/ProbeSet.h"
#include "probes/VolumeRank.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::probes {

std::string volumeRanksPath(const std::string& probeFile); // probeFile + ".ranks.json"

nlohmann::json volumeRanksJson(const VolumeRanks& r);
// Throws pb::Error "PATH: problem" for anything that is not a ranks file of this version.
VolumeRanks parseVolumeRanks(const nlohmann::json& j, const std::string& path);

void writeVolumeRanks(const std::string& path, const VolumeRanks& r); // atomic
VolumeRanks readVolumeRanks(const std::string& path);

// "" when `r` ranks exactly the volumes of `set` (input hash, names in file order), else why not.
std::string volumeRanksProblem(const VolumeRanks& r, const ProbeSet& set);

// Sets set.ranks from probeFile's sidecar when it exists and matches; otherwise leaves them
// empty with set.ranksNote saying why (missing, stale, unreadable). Never throws for the
// sidecar: only gi.volume_lod=rank_budget_mib needs it, and that reports the note.
void attachVolumeRanks(ProbeSet& set, const std::string& probeFile);
// readProbeFile + attachVolumeRanks: what every command that renders with a probe file uses.
ProbeSet readProbeFileWithRanks(const std::string& path);

} // namespace pb::probes
