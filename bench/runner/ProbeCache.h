#pragma once
// The probes a benchmark renders with when no probe file is given: the volumes of `volumes`
// ("auto", "auto-uniform" or a volumes TOML file, as `probebench bake --volumes`: auto stored
// sparse, the others dense), 128 rays, 2 bounces, RGBA16F, the scene's daylight (plus a
// volumes file's scenarios), baked once per input hash and Embree ISA (probes/bake/EmbreeIsa.h)
// into a cache folder (the bake cache of ProbeFile.h: a stale or damaged file is re-baked,
// never trusted).
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace pb::bench {

// $XDG_CACHE_HOME/probebench, else ~/.cache/probebench, else ./.probebench-cache.
std::string defaultProbeCacheDir();

// The cached or freshly baked probes; `path` receives the cache file, `progress` a line when
// a bake starts.
probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& volumes,
                             const std::string& cacheDir, std::string* path = nullptr,
                             const std::function<void(const std::string&)>& progress = {});

} // namespace pb::bench
