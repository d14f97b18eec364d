#pragma once
// Everything a probe file holds: the volumes, per-probe state (relocation offset, validity),
// visibility per volume (geometry only, shared by every scenario) and irradiance per
// scenario and volume. The bake produces it, ProbeFile writes/reads it, the CPU sampler and
// the GPU pass consume it.
#include "probes/ProbeLayout.h"
#include "probes/ProbeVolume.h"
#include "probes/Scenario.h"
#include "probes/StorageFormat.h"
#include "probes/VolumeRank.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pb::probes {

// What the bake was asked to do (all part of the input hash).
struct BakeSettings {
    int raysPerProbe = 256;
    // Bounce passes (Baker.h): 0 = until the light converges (kConvergedChange), N = exactly N
    // (1 = the direct light at the hits).
    int bounces = 0;
    std::uint64_t seed = 1;
    StorageFormat format = StorageFormat::Rgba16f;
    bool relocate = true;            // move probes up to kMaxRelocation cell out of geometry
    float backfaceThreshold = 0.25f; // back-face hit ratio above which a probe is invalid
    // Points sampled on the emissive triangles per probe, pass and round, weighted against
    // the rays by MIS (probes/bake/RadiancePass.h EmitterSampling); 0: the rays alone. A bake
    // input (hashed), not stored in the probe file.
    int emitterSamples = 512;
    // Points sampled on the directly lit surfaces per probe, pass and round (light that the
    // sun and the punctual lights put on a surface, reflected: probes/bake/LitSurfaces.h),
    // weighted against the rays by MIS; 0: the rays alone. A bake input (hashed, stored).
    int litSamples = 128;
    // The converged bake: a probe whose estimated irradiance noise (relative standard error of
    // its texels, NoiseRounds.h) is above this after a pass's first round of
    // rays gets more rounds - a fresh ray rotation and fresh emitter samples each, averaged -
    // until it is below or has had kMaxNoiseRounds. 0: one round (no noise control). A bake
    // input (hashed), not stored in the probe file.
    float noiseTarget = 0.03f;
};

// The converged bake (bounces = 0) stops after the pass that added less than this share of
// the light (per traced probe its increment's luminance over its total, averaged over the
// probes), or after kMaxBouncePasses passes.
constexpr float kConvergedChange = 0.01f;
constexpr int kMaxBouncePasses = 24;
// Rays per probe of pass `pass` (1-based): the full count for the first two, then halved per
// pass down to kMinIncrementRays: each pass carries less light than the one before, so the
// same relative noise in it costs the final irradiance less.
constexpr int kMinIncrementRays = 32;
inline int passRays(int raysPerProbe, int pass) {
    if (pass <= 2) return raysPerProbe;
    const int shift = pass - 2 > 20 ? 20 : pass - 2;
    const int halved = raysPerProbe >> shift;
    const int floor = raysPerProbe < kMinIncrementRays ? raysPerProbe : kMinIncrementRays;
    return halved > floor ? halved : floor;
}
// Bounces of the placement's trial bakes when the bake converges (bounces = 0): enough for the
// search to compare lattices, at a bounded cost.
constexpr int kConvergedTrialBounces = 2;

// The most rounds of rays a probe gets per pass under a noise target (so at most this many
// times the rays of a plain bake, for the probes that need them).
constexpr int kMaxNoiseRounds = 16;

// Relocation never moves a probe further than this fraction of its cell along any axis.
constexpr float kMaxRelocation = 0.45f;

struct ProbeState {
    glm::vec3 offset{0.0f};  // relocation, world units along the volume's LOCAL axes
    bool valid = true;       // false: inside geometry (excluded by the sampler)
    float backfaceRatio = 0; // diagnostic: share of rays that hit single-sided back faces
    // false: sparse storage left the probe out (SparseLayout.h); it then owns no visibility
    // tile, and no irradiance tile either unless `irradianceOnly`.
    bool stored = true;
    // Sparse storage kept only the probe's irradiance tile, no visibility tile (issue 18): it
    // is no corner of a surface cell, so every point that reads it lies in a cell free of
    // geometry and sees it unoccluded; lookups give it visibility weight 1. Then `stored` is
    // false and `valid` true. A third of a stored probe's bytes (rgba16f: 512 of 1536).
    bool irradianceOnly = false;
    // The lattice point itself is inside geometry (back-face ratio above the threshold before
    // relocation moved the probe out). The SH technique looks probes up at their lattice points,
    // so for it such a probe is invalid (probes/sh/ShIrradiance.h shProbeValid). Stored in the
    // SH record.
    bool insideAtLattice = false;
};

// The probe has an irradiance tile (and SH): stored, or irradiance-only.
inline bool ownsIrradiance(const ProbeState& s) { return s.stored || s.irradianceOnly; }

// What sparse storage keeps of the valid probes it leaves out (issue 18; SparseStorage.h):
// - StandIns: nothing (they become invalid; lookups read their nearest stored probe,
//   AbsentProbeFill.h).
// - Ranked: the ones whose stand-in is furthest from their own light keep their irradiance
//   tile (as Irradiance), as many as a memory budget allows; the rest are read as stand-ins
//   (store/FreeSpaceTiles.h). The default of `bake`.
// - Irradiance: every one keeps its irradiance tile and SH, no visibility
//   (ProbeState::irradianceOnly): a mid-air lookup then gives the dense bake's light, for a
//   third of a stored probe's bytes each (`bake --free-space all`).
enum class FreeSpace : std::uint8_t { StandIns, Ranked, Irradiance };

struct ProbeSet {
    std::uint64_t inputHash = 0;
    BakeSettings settings;
    // Sparse sets: the free-space choice the bake made and Ranked's budget (0: the default
    // share), as the bake request had them (part of the input hash; the file's free-space
    // record). Dense sets: StandIns, 0.
    FreeSpace freeSpace = FreeSpace::StandIns;
    double freeSpaceBudgetBytes = 0.0;
    std::vector<ProbeVolume> volumes;
    std::vector<std::vector<ProbeState>> states; // [volume][probe]
    std::vector<ProbeTexture> visibility;        // [volume]
    std::vector<Scenario> scenarios;
    std::vector<std::vector<ProbeTexture>> irradiance; // [scenario][volume]
    // The SH technique's probes (probes/sh/ShIrradiance.h): [scenario][volume][probe * 9 +
    // coefficient], radiance SH in the volume's local frame, from the same bake. Empty: a file
    // from before version 6 (re-bake for gi.technique=sh_l1|sh_l2).
    std::vector<std::vector<std::vector<glm::vec3>>> sh;
    // Not part of the probe file: the volume ranks of its sidecar FILE.ranks.json when one was
    // read and matches (VolumeRanksFile.h); otherwise empty and `ranksNote` says why.
    std::optional<VolumeRanks> ranks;
    std::string ranksNote;

    StorageFormat format() const { return settings.format; }
    bool hasSh() const { return !sh.empty(); }
    // -1 when absent.
    int findScenario(const std::string& name) const;
    std::size_t probeCount() const;
    std::size_t invalidCount() const;
    std::size_t storedCount() const; // probes that own a tile (all of them unless sparse)
};

} // namespace pb::probes
