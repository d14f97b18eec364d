#pragma once
// The storage scale of a scenario's irradiance: a power of two s with stored = E * s, chosen
// at bake time so that the scenario's irradiance sits in the comfortable range of the storage
// format (fp16 and BC6H UF16: normals 6.1e-5 .. 65504). Without it a scene lit at 1e6 lux is
// clamped to 65504 when stored, and one lit at 1e-6 is stored as fp16 denormals (BC6H at such
// magnitudes is worse). Everything on the CPU sees true values: decodeStored divides by s
// (exact: a power of two), so the sampler, nesting blend, ranking, tune and stress reference
// never see the scale; the GPU multiplies the fetched irradiance by 1/s, folded into
// gi.guard_exposure's per-fetch multiply (shaders/common_ddgi.glsl).
//
// The rule (chooseStorageScale), with M the largest finite RGB texel of every volume of the
// scenario:
//   - rgba32f, M = 0, or kScaleLow <= M <= kScaleHigh: s = 1, so an ordinary bake is stored
//     bit for bit as without a scale;
//   - otherwise s = 2^floor(log2(kScaleHigh / M)), M * s in (kScaleHigh / 2, kScaleHigh]:
//     the brightest texel 2 stops under fp16's maximum (headroom for BC6H endpoint error),
//     and 28 stops of the format's normals below it; s is clamped to [2^-64, 2^64].
#include "probes/ProbeLayout.h"
#include "probes/StorageFormat.h"

#include <string>
#include <vector>

namespace pb::probes {

inline constexpr float kScaleHigh = 16384.0f;    // 2^14: 4x under 65504
inline constexpr float kScaleLow = 1.0f / 64.0f; // 2^-6: 8 stops above fp16's normals
inline constexpr int kMaxScaleExponent = 64;     // |log2 s| limit, also for files

// Largest finite RGB value of the textures (alpha is always 1 and never scaled).
float maxIrradiance(const std::vector<ProbeTexture>& textures);
float chooseStorageScale(float maxIrradiance, StorageFormat f);

// true when s is a power of two with |log2 s| <= kMaxScaleExponent (NaN, inf, 0, negatives,
// and anything else false): what a probe file may hold.
bool isValidStorageScale(float s);

// Picks the scale for one scenario's textures (one per volume) and sets storageScale on
// each; quantise() then stores texels * scale.
void assignStorageScale(std::vector<ProbeTexture>& scenarioTextures, StorageFormat f);

} // namespace pb::probes
