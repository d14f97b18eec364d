#pragma once
// Which of the probes that sparse storage leaves out keep an irradiance tile (issue 18; the
// default FreeSpace::Ranked, SparseStorage.h).
//
// A lookup in the air reads a left-out probe as its stand-in, the nearest stored probe
// (AbsentProbeFill.h). Most stand-ins see nearly the light the probe itself would give; a few,
// beside a wall or a window where the light changes within a cell, are off by 2x and more
// (studies/results/2026-11-29-irradiance-only-half-tiles.md). Only those need their own tile.
// So after the bake, which traced every left-out probe as the dense bake does:
//   1. each left-out probe (valid, outside geometry) is scored by how far its stand-in's light
//      is from its own: the largest relative luminance difference over the 6 local axis
//      directions and every scenario, floored at a tenth of the stored probes' mean luminance
//      so a dark corner's tiny absolute error does not rank first;
//   2. the highest scores keep an irradiance tile (ProbeState::irradianceOnly), as many as fit
//      the memory budget - the set's memory (one scenario resident, packed tiles and the
//      indirection, as memoryReport counts it) stays within it. Ties keep the lower volume,
//      then the lower probe index, so the choice is the same on every machine.
#include "probes/ProbeSet.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// The share of a sparse set's memory these tiles are meant to get: an adaptive placement under
// a budget that leaves them less is made again into (1 - share) of it when that costs at most
// 5% of its spacing (AutoPlacement.h), and a bake without a budget lets the tiles add up to
// share / (1 - share) of its stored bytes. 5%: on the
// built-in scenes' default placements the tiles that bring every mid-air lookup within 15% of
// the dense one cost 2.1-7.2% of the stored bytes, and the placements leave 2.8-16.6% of
// their budget unused (studies/results/2026-11-29-irradiance-only-half-tiles.md).
constexpr double kFreeSpaceTileShare = 0.05;

struct FreeSpaceTileChoice {
    // [volume][probe]: 1 = left out, keeps its irradiance tile.
    std::vector<std::vector<std::uint8_t>> tiles;
    std::size_t candidates = 0; // left-out probes outside geometry (each could have a tile)
    std::size_t chosen = 0;     // how many got one
    float worstLeft = 0.0f;     // the highest score of the probes left to their stand-in
};

// The memory budget the tiles fill when the bake has none: the stored bytes grown so the
// tiles get kFreeSpaceTileShare of the whole.
double defaultFreeSpaceBudget(double storedBytes);

// Per probe of every volume of `traced` (every valid probe traced, tiles in the dense layout,
// before storeOnly): its stand-in's score as in step 1 above; 0 for probes `keep` stores and
// for invalid ones, and -1 for a left-out probe with no stored probe in its volume (no
// stand-in at all: ranks first).
std::vector<std::vector<float>> standInErrors(const ProbeSet& traced,
                                              const std::vector<std::vector<std::uint8_t>>& keep);

// Steps 1 and 2: the tiles within `budgetBytes` (<= 0: defaultFreeSpaceBudget of what `keep`
// stores). `keep` as storeOnly's.
FreeSpaceTileChoice chooseFreeSpaceTiles(const ProbeSet& traced,
                                         const std::vector<std::vector<std::uint8_t>>& keep,
                                         double budgetBytes);

} // namespace pb::probes
