#pragma once
// The probes a benchmark renders with when no probe file is given: `probebench bake --volumes
// VOLUMES --rays 128 --noise-target 0.015` (benchBakeFlags; every other option bake's default:
// bounces until converged, RGBA16F, day, auto stored sparse), obtained as bake obtains them
// (probes/obtain/ObtainProbes.h: the placement cache first, so a cache hit places nothing) into
// a file of the cache folder named by the options and the Embree ISA (probeCachePath). `bake
// --volumes VOLUMES` with those flags and `--out F` writes the same bytes.
//
// Why these two: these probes are the `reference` profile's, the yardstick of every accuracy
// figure, so their own noise should stay out of the figures, and fewer rays with a stricter
// noise target get there for fewer rays than more rays for every probe: the rounds go where
// the noise is. Against the path-traced truth (courtyard, worst-case view, 320x180): 128 rays
// at the bake's 3% target FLIP 0.032, 256 rays 0.030, 512 rays 0.026, 128 rays at 1.5% 0.029
// with 12.3 M rays against 26.7 M (studies/results/2026-12-03-truth-gbuffer-albedo.md).
#include "probes/ProbeSet.h"
#include "probes/obtain/BakeOptions.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace pb::bench {

// $XDG_CACHE_HOME/probebench, else ~/.cache/probebench, else ./.probebench-cache.
std::string defaultProbeCacheDir();

constexpr int kBenchRaysPerProbe = 128;
constexpr float kBenchNoiseTarget = 0.015f;

// What the bench asks the bake for: bake's defaults, kBenchRaysPerProbe rays, noise target
// kBenchNoiseTarget, these volumes.
probes::BakeOptions benchBakeOptions(const std::string& volumes);
// The same as `bake` flags ("--rays 128 --noise-target 0.015"), for help texts and notes.
std::string benchBakeFlags();

// The cached or freshly baked probes; `path` receives the cache file, `progress` a line when
// a placement ran and when a bake starts, `passes` the first scenario's bounce passes when
// baked here (0 when read from the cache: the file does not record them).
probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& volumes,
                             const std::string& cacheDir, std::string* path = nullptr,
                             const std::function<void(const std::string&)>& progress = {},
                             int* passes = nullptr);

} // namespace pb::bench
