#pragma once
// The probes a benchmark renders with when no probe file is given: `probebench bake --volumes
// VOLUMES --rays 128` (every other option bake's default: bounces until converged, RGBA16F, day, auto stored
// sparse), obtained as bake obtains them (probes/obtain/ObtainProbes.h: the placement cache
// first, so a cache hit places nothing) into a file of the cache folder named by the options
// and the Embree ISA (probeCachePath). `bake --rays 128 --volumes VOLUMES --out F` writes the
// same bytes.
#include "probes/ProbeSet.h"
#include "probes/obtain/BakeOptions.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace pb::bench {

// $XDG_CACHE_HOME/probebench, else ~/.cache/probebench, else ./.probebench-cache.
std::string defaultProbeCacheDir();

// What the bench asks the bake for: bake's defaults, 128 rays, these volumes.
probes::BakeOptions benchBakeOptions(const std::string& volumes);

// The cached or freshly baked probes; `path` receives the cache file, `progress` a line when
// a placement ran and when a bake starts, `passes` the first scenario's bounce passes when
// baked here (0 when read from the cache: the file does not record them).
probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& volumes,
                             const std::string& cacheDir, std::string* path = nullptr,
                             const std::function<void(const std::string&)>& progress = {},
                             int* passes = nullptr);

} // namespace pb::bench
