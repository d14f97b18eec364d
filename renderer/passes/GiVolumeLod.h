#pragma once
// gi.volume_lod applied to a probe set: which volumes the GPU loads (GL-free, so it is unit
// tested without a context). Omitting a volume omits the volumes nested in it: a child only
// refines its parent and its outer ring was blended towards it.
#include "probes/ProbeSet.h"
#include "profile/VolumeLod.h"

#include <cstddef>
#include <vector>

namespace pb::render {

// GPU bytes of one volume with one scenario resident: irradiance + visibility in the set's
// storage format + the per-probe state texture (RGBA32F).
std::size_t gpuVolumeBytes(const probes::ProbeVolume& v, probes::StorageFormat format);

// Indices into set.volumes of the volumes to load, in file order. Throws pb::Error when a
// name in omit: is not in the set or when budget_mib: cannot hold a root volume.
std::vector<int> selectVolumes(const probes::ProbeSet& set, const profile::VolumeLod& lod);

} // namespace pb::render
