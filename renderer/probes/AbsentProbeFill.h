#pragma once
// Lookups in free space from a sparse set (issue 18): sparse storage keeps the probes of
// surface cells and a coarse lattice through the free space (SparseStorage.h); a probe it left
// out "absent" is read, by every lookup, as its nearest stored probe - that probe's position
// (through the offset), visibility and irradiance. A point in the air between surfaces then
// interpolates real probes, as a dense bake would, instead of getting weight 0.
//
// Only absent probes OUTSIDE geometry are filled: one inside geometry (its back-face ratio above
// the bake's threshold) stays invalid, as it is in the dense bake, so a surface cell - whose
// corners are all stored or inside geometry - is looked up exactly as before, bit for bit.
//
// Computed from the in-memory states alone (presence, back-face ratio, offsets), so the file
// format does not change; the CPU sampler (ProbeSampler), the GPU's state texture (GpuProbes:
// offset and tile code) and the texture-cache model (TileLayout) all apply the same fill.
// It costs no texture memory: a filled probe owns no tile, its state texel points at its
// source's tile.
#include "probes/ProbeSet.h"

#include <vector>

namespace pb::probes {

// True when sparse storage left the probe out although it lies outside geometry, and kept no
// irradiance tile of it (an irradiance-only probe, ProbeState::irradianceOnly, is read as
// itself): a lookup reads a stand-in for it. `backfaceThreshold` is the bake's (BakeSettings).
bool fillable(const ProbeState& s, float backfaceThreshold);

// Per probe of `v`: the probe a lookup reads in its place. Itself when stored or inside
// geometry; for a fillable probe the stored valid probe nearest to its grid position (world
// distance between grid points; ties: the lower index), or -1 when the volume stores none.
// Empty when nothing is fillable (dense volumes): callers then use the states as they are.
std::vector<int> fillSources(const ProbeVolume& v, const std::vector<ProbeState>& states,
                             float backfaceThreshold);

// The states as a lookup sees them: a filled probe is valid and sits where its source does
// (offset = source's grid point + source's offset - own grid point, in local axes; this may
// exceed kMaxRelocation: these states are never written to a file). `sources` as fillSources.
std::vector<ProbeState> lookupStates(const ProbeVolume& v, const std::vector<ProbeState>& states,
                                     const std::vector<int>& sources);

} // namespace pb::probes
