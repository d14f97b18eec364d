#pragma once
// gi.volume_lod applied to a probe set: which volumes the GPU loads, what they cost in GPU
// memory and the order the apply pass draws them. GL-free and beside the switch that asks for it:
// the renderer's GpuProbes, the frame's memory report and the cost model all apply the same
// rules, so none of them links another to get them. Omitting a volume omits the volumes nested
// in it: a child only refines its parent and its outer ring was blended towards it.
#include "probes/ProbeSet.h"
#include "profile/VolumeLod.h"

#include <cstddef>
#include <vector>

namespace pb::profile {

// GPU bytes of one volume with one scenario resident: irradiance + visibility in the set's
// storage format + the per-probe state texture (RGBA32F).
std::size_t gpuVolumeBytes(const probes::ProbeVolume& v, probes::StorageFormat format);
// The same for volume `v` of a baked set: a sparse volume (probes/store/SparseLayout.h) counts only
// its packed tiles (+ the state texture, its indirection), as GpuProbes uploads it.
std::size_t gpuVolumeBytes(const probes::ProbeSet& set, std::size_t v);

// Indices into set.volumes of the volumes to load, in file order. Throws pb::Error when a
// name in omit: is not in the set, when budget_mib: cannot hold a root volume, or when
// rank_budget_mib: has no ranks (ProbeSet::ranks) or keeps no volume.
std::vector<int> selectVolumes(const probes::ProbeSet& set, const VolumeLod& lod);

// rank_budget_mib's order of dropping (needs set.ranks), peeling the tree from its leaves:
// among the kept volumes with no kept child, the one losing the least accuracy per byte
// (VolumeRank::loss / its own GPU bytes; ties: the larger, then the later in the file) goes
// first, so a parent goes only after its children and a smaller budget keeps a subset of what
// a larger one keeps. Returns the volumes in that order, each with the bytes still kept after
// it went (the last entry keeps 0). A budget of B bytes keeps what remains after the first
// step whose remaining bytes fit B.
struct RankDropStep {
    int volume = 0;            // file index of the volume dropped
    std::size_t keptBytes = 0; // GPU bytes still kept after this step
};
std::vector<RankDropStep> rankDropOrder(const probes::ProbeSet& set);

// The apply pass's draw order for "each draw overwrites": largest box first, among equal boxes
// the later file index first, so the last draw covering a pixel is the CPU sampler's choice
// (smallest box, ties: first in the file). boxVolumes[i] = ProbeVolume::boxVolume() of the
// volume at file index fileIndices[i]; returns positions i.
std::vector<int> volumeDrawOrder(const std::vector<float>& boxVolumes,
                                 const std::vector<int>& fileIndices);

} // namespace pb::profile
