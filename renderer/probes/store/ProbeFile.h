#pragma once
// The probe data file (.pbp): one binary file with all volumes and scenarios.
//
// Little-endian, no padding, in this order (README.md "File format" has the full table):
//   magic "PBPROBES", u32 version, u64 file size, u64 input hash, bake settings, tile sizes,
//   volumes, scenarios, per-scenario storage scales, per-volume probe states, the sparse
//   storage record (per volume dense / sparse + presence bitmap; sparse volumes store only
//   their present probes' tiles, packed: SparseLayout.h), per-volume visibility bytes,
//   per-scenario per-volume irradiance bytes (each texture as u64 size + bytes in the storage
//   format), u64 FNV-1a checksum of every byte before it. Version 1 files (no scales, every
//   volume dense) still read; version 2 was a development format that never shipped.
// Written atomically (temporary file + rename). Reading checks magic, version, size and
// checksum before parsing, and every size while parsing: a wrong, truncated or corrupted
// file gives a one-line pb::Error naming the file, never a crash or garbage.
#include "probes/ProbeSet.h"

#include <cstdint>
#include <optional>
#include <string>

namespace pb::probes {

inline constexpr char kProbeFileMagic[8] = {'P', 'B', 'P', 'R', 'O', 'B', 'E', 'S'};
// 3: per-scenario storage scales (StorageScale.h) and the sparse storage record.
// 4: the converged bake's settings (emitter samples, noise target) after the backface threshold.
// 5: the lit-surface samples after the noise target.
// 6: the SH probes (probes/sh/ShIrradiance.h) after the irradiance: u8 present, then per volume and
//    probe u8 insideAtLattice, then per scenario, volume and stored probe 9 x RGB f32 (older
//    files read with no SH).
// 7: sparse volumes' irradiance-only probes (issue 18): a second bitmap after the presence
//    bitmap, their irradiance tiles packed after the stored ones, their SH kept.
// 8: the free-space record (issue 18) after the SH record: u8 FreeSpace, f64 Ranked's budget
//    (older files: StandIns, or Irradiance when any probe is irradiance-only; budget 0).
inline constexpr std::uint32_t kProbeFileVersion = 8;
// The version the bake's input hash names (BakeHash.cpp): bumped with kProbeFileVersion when a
// file of the same inputs would hold something else. Version 8 only writes down what version
// 7 files imply (their free space), so a version 7 file stays up to date for the bake cache.
inline constexpr std::uint32_t kProbeFileContentVersion = 7;
inline constexpr std::uint32_t kProbeFileFirstVersion = 1; // oldest version still read

std::vector<std::uint8_t> serializeProbeSet(const ProbeSet& set);
// `path` only names the source in errors.
ProbeSet parseProbeSet(const std::vector<std::uint8_t>& bytes, const std::string& path);

void writeProbeFile(const std::string& path, const ProbeSet& set);
ProbeSet readProbeFile(const std::string& path);

// The bake cache: the probe set at `path` when it exists, reads cleanly and was baked from
// inputs with hash `inputHash`; otherwise nothing, with `why` saying so (missing, stale, or
// the read error) - a damaged file is re-baked, never trusted.
std::optional<ProbeSet> readCachedProbeFile(const std::string& path, std::uint64_t inputHash,
                                            std::string* why = nullptr);

} // namespace pb::probes
