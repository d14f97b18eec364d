#pragma once
// The probes a benchmark renders with when none are given: `--volumes auto` placement (nested
// volumes, so gi.multi_volume has work), 128 rays, 2 bounces, RGBA16F, the scene's daylight,
// baked once per scene and input hash into a cache folder (the bake cache of ProbeFile.h: a
// stale or damaged file is re-baked, never trusted).
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace pb::bench {

// $XDG_CACHE_HOME/probebench, else ~/.cache/probebench, else ./.probebench-cache.
std::string defaultProbeCacheDir();

// The cached or freshly baked probes; `path` receives the cache file, `progress` a line when
// a bake starts.
probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& cacheDir,
                             std::string* path = nullptr,
                             const std::function<void(const std::string&)>& progress = {});

} // namespace pb::bench
