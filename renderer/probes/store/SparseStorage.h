#pragma once
// Which probes sparse storage keeps (`bake --sparse`): a probe is stored when it is valid
// and a corner of a grid cell that static surface passes through. A surface point is shaded
// from the 8 corner probes of the cell its (unbiased) position falls in (ProbeSampler.h step
// 3; a root's fade margin counts to its boundary cells), so dropping every other probe
// changes no surface's irradiance (tested); only lookups in empty air (dynamic objects) lose
// them and get weight 0, i.e. the caller's fallback.
//
// Exact geometry, not the baked visibility (SparseCandidates.h): the same test runs before
// the bake, so the placement's memory budget (AutoPlacement.h) counts exactly what the bake
// will store (less only the probes that then bake invalid).
#include "probes/ProbeSet.h"
#include "probes/StaticTriangles.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// A surface within this fraction of a cell of a cell's face counts for the cell behind the
// face too (SparseStorage.cpp says why).
constexpr float kSurfaceCellMargin = 0.01f;

// Per probe of `v`: 1 when it is a corner of a cell with surface in it. `root`: the volume
// has no parent (its influence reaches kEdgeFadeCells beyond its box).
std::vector<std::uint8_t> surfaceCornerProbes(const ProbeVolume& v, bool root,
                                              const std::vector<WorldTriangle>& triangles);

// How many probes each volume stores sparse (surface corners; validity unknown before the
// bake, so all count).
std::vector<std::size_t> sparseProbeCounts(const std::vector<ProbeVolume>& volumes,
                                           const std::vector<WorldTriangle>& triangles);

// Marks every probe that is invalid or no surface corner as not stored (and invalid) and
// zeroes its tiles, exactly as writing and reading the file would.
void applySparseStorage(ProbeSet& set, const std::vector<WorldTriangle>& triangles);

// The same for any choice: keep[volume][probe] != 0 and valid stays stored, the rest becomes
// absent. Sizes must match the set's volumes.
void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep);

} // namespace pb::probes
