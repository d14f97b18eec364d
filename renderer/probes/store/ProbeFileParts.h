#pragma once
// Split bakes (`bake --split scenario --part I/N`, `probebench bake-merge`): the part file
// (.pbpart) one machine writes, and the merge that joins every part of one bake into the
// probe file a single bake writes, byte for byte.
//
// Why the merge is exact: the geometry pass (states, visibility) never follows the seed and
// every part runs it whole, and a scenario's radiance passes read only that scenario's
// previous pass and are seeded by the scenario's index in the whole bake (BakeRequest::
// onlyScenarios), so each part's scenarios are the whole bake's. The merge checks the parts'
// geometry bytes agree instead of trusting it. A sparse bake's ranked free-space tiles
// (FreeSpaceTiles.h) rank every scenario's light: each part keeps every left-out probe's tile,
// and the merge makes the whole bake's choice from the joined scenarios.
//
// Part file, little-endian: magic "PBPPART1", u32 version, u32 part, u32 parts, u32 the whole
// bake's scenario count, u32 held scenario count + u32 index each, u64 size + the bytes of a
// probe file (ProbeFile.h) holding those scenarios under the whole bake's input hash, u64
// FNV-1a checksum of every byte before it.
#include "probes/ProbeSet.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pb::probes {

inline constexpr char kProbePartMagic[8] = {'P', 'B', 'P', 'P', 'A', 'R', 'T', '1'};
inline constexpr std::uint32_t kProbePartVersion = 1;

struct ProbeFilePart {
    std::uint32_t part = 0, parts = 1;
    std::uint32_t totalScenarios = 0;     // of the whole bake
    std::vector<std::uint32_t> scenarios; // the whole bake's indices this part holds, ascending
    ProbeSet set;                         // holds exactly those scenarios, in that order
};

// Which scenarios (indices into `total`) part `part` of `parts` bakes: contiguous blocks, the
// first `total % parts` parts one more. Throws pb::Error when parts < 1, part >= parts or
// parts > total (a part with nothing to bake).
std::vector<std::size_t> scenarioSplit(std::size_t total, int part, int parts);

std::vector<std::uint8_t> serializeProbeFilePart(const ProbeFilePart& p);
ProbeFilePart parseProbeFilePart(const std::vector<std::uint8_t>& bytes, const std::string& path);
void writeProbeFilePart(const std::string& path, const ProbeFilePart& p);
ProbeFilePart readProbeFilePart(const std::string& path);

// Joins the parts (any order) of one split bake. Throws pb::Error naming the offending file
// (`paths[i]` names parts[i]) when parts come from different bakes, one is missing or given
// twice, or their geometry differs.
ProbeSet mergeProbeFileParts(const std::vector<ProbeFilePart>& parts,
                             const std::vector<std::string>& paths);

} // namespace pb::probes
