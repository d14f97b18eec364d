#pragma once
// Which probes sparse storage keeps (`bake --sparse`): a probe is stored when it is valid
// and a corner of a grid cell that static surface passes through, or on the coarse
// free-space lattice (kFreeSpaceLatticeStep). A surface point is shaded
// from the 8 corner probes of the cell its (unbiased) position falls in (ProbeSampler.h step
// 3; a root's fade margin counts to its boundary cells), so dropping every other probe
// changes no surface's irradiance (tested); lookups in empty air (dynamic objects) read the
// free-space lattice and stand-ins for the absent probes (AbsentProbeFill.h).
//
// Exact geometry, not the baked visibility (SparseCandidates.h): the same test runs before
// the bake, so the placement's memory budget (AutoPlacement.h) counts exactly what the bake
// will store (less only the probes that then bake invalid).
#include "probes/ProbeSet.h"
#include "raytrace/StaticTriangles.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pb::probes {

// A surface within this fraction of a cell of a cell's face counts for the cell behind the
// face too (SparseStorage.cpp says why).
constexpr float kSurfaceCellMargin = 0.01f;

// Per probe of `v`: 1 when it is a corner of a cell with surface in it. `root`: the volume
// has no parent (its influence reaches kEdgeFadeCells beyond its box).
std::vector<std::uint8_t> surfaceCornerProbes(const ProbeVolume& v, bool root,
                                              const std::vector<raytrace::WorldTriangle>& triangles);

// The free-space lattice (issue 18): every probe whose grid coordinates are all multiples of
// this step is kept too, so the air between surfaces holds a coarse level of real probes -
// the stand-ins that absent probes are read as (AbsentProbeFill.h) are then at most one cell
// per axis away. 2 keeps 1/8 of the free space's probes; without it (the nearest surface
// probe as the stand-in) mid-air lookups on the built-in scenes were off by 15-21% on average
// and by up to 13x (studies/findings/mid-air-options.md, "Mid-air options").
constexpr int kFreeSpaceLatticeStep = 2;

// Per probe of `v`: 1 on the free-space lattice (every coordinate a multiple of the step).
std::vector<std::uint8_t> freeSpaceLatticeProbes(const ProbeVolume& v);

// What sparse storage keeps of `v` (validity aside): the surface corners and the free-space
// lattice.
std::vector<std::uint8_t> sparseKeptProbes(const ProbeVolume& v, bool root,
                                           const std::vector<raytrace::WorldTriangle>& triangles);

// sparseKeptProbes of every volume of a set (`volumes`: parents before children, as
// validateVolumes checks; a volume without a parent is a root).
std::vector<std::vector<std::uint8_t>>
sparseKeptMasks(const std::vector<ProbeVolume>& volumes,
                const std::vector<raytrace::WorldTriangle>& triangles);

// The ones of each mask: how many probes each volume stores sparse (validity unknown before
// the bake, so all count).
std::vector<std::size_t> keptCounts(const std::vector<std::vector<std::uint8_t>>& masks);

// keptCounts(sparseKeptMasks(volumes, triangles)).
std::vector<std::size_t> sparseProbeCounts(const std::vector<ProbeVolume>& volumes,
                                           const std::vector<raytrace::WorldTriangle>& triangles);

// What lookups in free space cost (issue 18): the stored probes that only the free-space
// lattice keeps (on it, and a corner of no surface cell). The bake summary reports them.
std::size_t freeSpaceOnlyProbes(const ProbeSet& set,
                                const std::vector<raytrace::WorldTriangle>& triangles);

// FreeSpace (ProbeSet.h): what sparse storage keeps of the valid probes it leaves out.
// "stand-ins", "ranked", "all" (the `bake --free-space` values).
const char* freeSpaceName(FreeSpace f);
bool parseFreeSpace(const std::string& text, FreeSpace& out);

// Marks every probe that is invalid or no surface corner as not stored (and invalid, or
// irradiance-only) and zeroes what it no longer holds, exactly as writing and reading the
// file would. `budgetBytes`: Ranked's memory budget (chooseFreeSpaceTiles).
void applySparseStorage(ProbeSet& set, const std::vector<raytrace::WorldTriangle>& triangles,
                        FreeSpace freeSpace = FreeSpace::StandIns, double budgetBytes = 0.0);

// The same for any choice: keep[volume][probe] != 0 and valid stays stored, the rest becomes
// absent. Sizes must match the set's volumes. Ranked chooses its tiles from the set as given
// (every valid probe traced).
void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep,
               FreeSpace freeSpace = FreeSpace::StandIns, double budgetBytes = 0.0);

// The same with the tiles chosen: tiles[volume][probe] != 0 and valid, not kept, becomes
// irradiance-only.
void storeOnly(ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep,
               const std::vector<std::vector<std::uint8_t>>& tiles);

} // namespace pb::probes
