#pragma once
// The probe bake: Embree on all cores, every probe independent (same inputs + seed give
// identical bytes for any thread count).
//
//   1. geometry pass (once): relocation, classification, visibility  (GeometryPass.h)
//   2. per scenario, bounce passes: irradiance of every valid probe (RadiancePass.h),
//      octahedral borders, nested-ring blend (NestingBlend.h). Pass 1 traces the sky,
//      emission and the light reflected once (direct light at the hits); each later pass b
//      traces only the increment, the light pass b-1 added, looked up at its hits and
//      reflected once more, with fewer rays as the increments shrink (passRays). The probe's
//      irradiance is the sum. With BakeSettings::bounces = 0 the passes go on until the last
//      one added under kConvergedChange of the light (at most kMaxBouncePasses): all the
//      bounces, as a radiosity solver converges; otherwise exactly `bounces` passes.
//   3. quantise to the storage format (the sampler then sees what the GPU will sample)
#include "probes/ProbeSet.h"
#include "raytrace/RayScene.h"
#include "probes/store/SparseStorage.h"
#include "scene/Scene.h"

#include <functional>
#include <optional>
#include <string>

namespace pb::probes {

struct BakeRequest {
    std::vector<ProbeVolume> volumes;
    std::vector<Scenario> scenarios;
    BakeSettings settings;
    int threads = 0; // 0 = all cores; never changes the result
    // Sparse storage (SparseStorage.h): after the bake, only valid probes at the corners of
    // cells with static surface stay stored. Part of the input hash.
    bool sparse = false;
    // With `sparse`: what the valid probes left out keep (SparseStorage.h FreeSpace). Part of
    // the input hash unless StandIns. `bake` asks for Ranked.
    FreeSpace freeSpace = FreeSpace::StandIns;
    // With Ranked: the memory the set may use with its free-space tiles (one scenario
    // resident, as memoryReport counts it; `bake --volumes auto`: the placement's budget).
    // <= 0: defaultFreeSpaceBudget (FreeSpaceTiles.h). Part of the input hash with Ranked.
    double freeSpaceBudgetBytes = 0.0;
    // Probes traced before their indirect lookups are sorted and done (RadiancePass.h);
    // 0 = about 2^18 rays per slab. Memory and speed only: never changes the result.
    int slabProbes = 0;
    // Benchmark instrumentation (not an input): when set, receives every ray the passes
    // traced, so bench_bake can replay exactly the same rays against bare Embree.
    std::vector<raytrace::RecordedRay>* recordRays = nullptr;
    // Not an input either: trace against this BVH of `scene` instead of building one (the
    // placement's trial bakes bake one scene many times). It must be built from the same scene.
    const raytrace::RayScene* rayScene = nullptr;
    // The scenario split (`bake --split scenario`): bake only these indices of `scenarios`
    // (empty: all of them; ascending, no duplicates). A scenario's seed stream is its index in
    // `scenarios`, not its place among these, so each scenario of a partial bake is
    // byte-identical to the same scenario of the whole bake (ProbeFileMerge.h joins them). Not
    // an input: a partial bake's input hash is the whole bake's.
    std::vector<std::size_t> onlyScenarios;
    // Rays per probe of the geometry pass (relocation, validity, visibility); 0: the
    // settings' raysPerProbe. The update engine (renderer/respond) traces low-ray radiance
    // samples of probes that must sit where the file's full bake put them. An input (hashed
    // when set).
    int geometryRays = 0;
    // Not an input: a trial bake whose irradiance alone is read (the lattice search's,
    // PlacementError.h): no SH projection and no noise measurement (its set's SH stay zero
    // and its noise statistics empty); stored sparse with stand-ins, no geometry pass for the
    // probes sparse storage drops (their states stay default; the trial's surface lookups
    // read only kept probes). Its texels are the full bake's, bit for bit; in RGBA32F it keeps
    // no stored bytes (ProbeTexture::stored stays empty: nothing writes or uploads a trial)
    // and no input hash (ProbeSet::inputHash 0).
    bool irradianceOnly = false;
    // Not an input: the scene's staticBakeTriangles (raytrace/StaticTriangles.h), when the
    // caller has them already (the placement's trial bakes: gathering the apartment's 178k
    // triangles again for each of 25 trials cost about 2% of a default bake). Sparse storage
    // reads them; it must be what staticBakeTriangles(scene) returns.
    const std::vector<raytrace::WorldTriangle>* staticTriangles = nullptr;
    // Not an input: with `sparse`, sparseKeptProbes of each volume (SparseStorage.h), when the
    // caller has them already (the lattice search's budget check marks every trial's
    // surface cells before the trial bakes; each mark visits every triangle). Must be what
    // sparseKeptProbes returns for these volumes.
    const std::vector<std::vector<std::uint8_t>>* keptProbes = nullptr;
};

struct BakeProgress {
    std::string stage;    // e.g. "geometry", "day pass 2/2"
    std::size_t done = 0; // probes finished over all stages
    std::size_t total = 0;
};
using BakeProgressFn = std::function<void(const BakeProgress&)>;

// What storing in the chosen format cost, per texture: relative error of each channel,
// |stored - baked| / max(|baked|, 1e-3 * the texture's largest value).
struct QuantisationError {
    std::string volume, texture; // texture: "visibility" or "irradiance <scenario>"
    double maxRelative = 0.0, meanRelative = 0.0;
};

// Where the tracing time went, summed over passes (bench_bake reports it).
struct BakePhase {
    std::string name; // "geometry", "setup", "trace", "lookup", "convolve"
    double wallSeconds = 0.0, cpuSeconds = 0.0; // cpu: the whole process, all threads
};

// The edge, in cells, of the block BakeStats::noisiestRegion names: small enough to point at a
// place (a corner, a doorway), large enough to gather a noisy region's probes.
inline constexpr int kNoisyBlockCells = 4;

struct BakeStats {
    // invalidProbes: inside geometry, as the geometry pass classified them (sparse storage
    // then stores none of them, and marks its absent probes invalid too: ProbeCounts.h).
    std::size_t probes = 0, invalidProbes = 0, relocatedProbes = 0;
    std::size_t storedProbes = 0;              // all probes unless sparse
    std::vector<std::size_t> invalidPerVolume; // invalidProbes per volume
    std::uint64_t primaryRays = 0, shadowRays = 0;
    std::size_t triangles = 0;
    double seconds = 0.0;      // whole bake, wall clock
    double buildSeconds = 0.0; // Embree BVH build
    double traceSeconds = 0.0; // geometry + radiance passes (all the ray tracing)
    // CPU seconds of the whole process (all threads) over traceSeconds: unlike the wall time
    // it hardly changes when other processes share the cores (bench_bake).
    double traceCpuSeconds = 0.0;
    std::vector<BakePhase> phases; // traceSeconds split up (their sums)
    double quantiseSeconds = 0.0;  // encoding to the storage format
    // The converged bake (BakeSettings::noiseTarget): each traced probe's relative noise of
    // its final irradiance (all passes, NoiseRounds.h), per scenario - mean and 95th
    // percentile -, how many probe passes needed more than one round, how many probes stayed
    // above the target after kMaxNoiseRounds, and the primary rays those extra rounds traced.
    double noiseMean = 0.0, noiseP95 = 0.0;
    std::size_t noisyProbePasses = 0, tracedProbePasses = 0;
    std::size_t probesAboveTarget = 0, tracedProbes = 0; // tracedProbes: over the scenarios
    std::uint64_t extraRoundRays = 0;
    // Where the probes above the target after the round cap gather: the volume with most of
    // them and, in it, the block of kNoisyBlockCells^3 cells holding most (cells inclusive).
    // Empty when every probe met the target (or there was none).
    struct NoisyRegion {
        std::string volume;
        glm::ivec3 from{0}, to{0};
        std::size_t probes = 0, probesInVolume = 0;
    };
    std::optional<NoisyRegion> noisiestRegion;
    // The bounce passes each baked scenario ran (BakeSettings::bounces; 0 asks until the
    // light converges), and the share of its light the last pass added (1 for one pass).
    std::vector<int> passes;
    std::vector<double> lastChange;
    int threads = 1;
    std::vector<QuantisationError> quantisation;
    // FreeSpace::Ranked (FreeSpaceTiles.h): the left-out probes that could have a tile, how many
    // got one, and the highest stand-in score among those that did not.
    std::size_t freeSpaceCandidates = 0, freeSpaceTiles = 0;
    float freeSpaceWorstLeft = 0.0f;
};

// Throws pb::Error for invalid volumes, no scenario, rays < 1 or bounces outside [0, 64].
ProbeSet bakeProbes(const scene::Scene& scene, const BakeRequest& request,
                    BakeStats* stats = nullptr, const BakeProgressFn& progress = {});

// Everything the result depends on: scene geometry, materials, lights, volumes, scenarios,
// settings, the file format version and the bake's algorithm version.
std::uint64_t bakeInputHash(const scene::Scene& scene, const BakeRequest& request);

} // namespace pb::probes
