#pragma once
// The truth is expensive (minutes at high spp), so it is cached as the bake is: by a hash of
// everything the image depends on - the scene's content (geometry of every drawn instance,
// normals, UVs, materials, texture bytes, lights, sun, sky), the camera, the size, spp, depth,
// seed and kTruthAlgorithmVersion - in a folder (the probe cache folder by default). A stale or
// damaged entry is recomputed, never trusted.
#include "truth/PathTracer.h"

#include <cstdint>
#include <optional>
#include <string>

namespace pb::truth {

// Bump whenever the tracer's output changes for the same inputs.
constexpr std::uint32_t kTruthAlgorithmVersion = 4; // 2: the bake's alias table; 3: the camera hit's albedo as the GBuffer stores it; 4: stratified samples (ScrambledSobol.h)

std::uint64_t truthInputHash(const scene::Scene& scene, const scene::View& view,
                             const TruthSettings& settings);

// "<dir>/truth-<hash as 16 hex digits>.pfm"; the noise and note are kept beside it (.json).
std::string truthCachePath(const std::string& dir, std::uint64_t hash);

// The cached result, or nothing when absent, unreadable or not of the expected size.
std::optional<TruthResult> loadCachedTruth(const std::string& dir, std::uint64_t hash,
                                           const TruthSettings& settings);
// Writes both files (atomically); throws pb::Error naming the path on failure.
void storeCachedTruth(const std::string& dir, std::uint64_t hash, const TruthResult& result);

} // namespace pb::truth
