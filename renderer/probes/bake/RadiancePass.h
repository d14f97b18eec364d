#pragma once
// One bounce pass's irradiance, a slab of probes at a time: trace the pass's rays, shade what
// they hit, and convolve (ProbeConvolution.h).
//
// Radiance arriving along a ray (Lambert, all surfaces diffuse):
//   miss                          -> sky radiance of the scenario
//   back face of single-sided     -> 0 (the inside of geometry; also what classification counts)
//   otherwise, at x with normal n facing the ray origin:
//       L = emissive + albedo / pi * (E_direct(x, n) + E_indirect(x, n))
// E_direct: DirectLight.h. E_indirect: the PREVIOUS pass's probes read with the CPU sampler
// at (x, n, view = -ray) without edge fade (0 in the first pass, or outside every volume).
// So pass b carries light that bounced up to b times before reaching the probe.
//
// Why slabs: E_indirect is a full DDGI lookup per hit (8 probes, 16 bilinear fetches), and a
// lookup is bound by the cache misses on those probes' tiles, not by its arithmetic. So the
// hits of a whole slab of probes are traced first (trace), then looked up sorted by the grid
// cell they fall in (lookUp: the hits of one cell reuse the same 8 probe tiles from the
// cache), then every probe's radiance is finished and convolved (convolve). Each lookup is
// the same pure function of its hit as in a per-ray loop, so the result is bit for bit the
// same, for any slab size and thread count.
#include "core/ParallelFor.h"
#include "core/HugePages.h"
#include "probes/ProbeSampler.h"
#include "probes/Scenario.h"
#include "probes/bake/LitSurfaces.h"
#include "probes/bake/ProbeConvolution.h"
#include "raytrace/RayScene.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// Per thread: aligned to a cache line, since every ray increments one (ParallelFor.h).
struct alignas(kCacheLine) RayCounters {
    std::uint64_t primary = 0, shadow = 0;
};

// Next-event estimation toward the scene's emissive triangles (RayScene::emitters), at the
// probe itself. With samples M > 0, each traced probe also samples M points on the emitters
// (alias table by power, EmitterTable.h) and weights them against its N rays by the balance
// heuristic, with the rays' density taken as uniform on the sphere (1 / 4pi, what the
// convolution's normalised weights amount to):
//     a ray hitting an emitter keeps      L_e * N p_u / (N p_u + M p_l(omega))
//     a visible light sample adds to texel t   L_e * max(0, n_t.omega) / (N p_u + M p_l(omega))
// so emitted light is counted once, from whichever strategy samples it better: the light
// samples for small or distant emitters (a panel a few rays would miss), the rays for large
// and close ones. Only emitted radiance the probe sees directly is sampled so: light that
// bounced off a surface first is still the hits' shading (below), as before.
// A probe a quarter or more of whose rays hit emitters (inside a glowing room, against a light
// wall) takes no light samples: its rays sample those emitters well, and their normalised
// convolution is exact for a uniform radiance (RadiancePass.cpp).
// samples = 0: the rays alone (what SurfaceGather uses). The stream seeds the pass; each
// probe draws from it by its probe key, so results do not depend on the thread count.
//
// Lit-surface samples (LitSurfaces.h) do the same for light that a surface reflects straight
// from the sun or a punctual light: with L > 0 of them, a hit on a lit patch keeps its direct
// part  albedo/pi E_direct  weighted  N p_u / (N p_u + L p_s(omega))  (p_s: the patch's
// solid-angle density), and each visible sample adds  albedo/pi E_direct(y) max(0, n_t.omega)
// / (N p_u + L p_s(omega))  to texel t. E_direct(y) is traced at the sampled point, so both
// strategies see the same function. (Sampling the reflected indirect light too, through the
// previous pass's probes, was tried on rooms and did no better: bench/README.md.) Every traced
// probe takes them: unlike emitters, lit surfaces are rarely a uniform quarter of the sphere, and
// where they are the balance heuristic leans on the rays.
struct EmitterSampling {
    int samples = 0;
    std::uint64_t stream = 0;
    int litSamples = 0;
    const LitSurfaces* lit = nullptr; // required when litSamples > 0
    // An increment pass (Baker.h): the rays carry only the light the previous pass added,
    // read at their hits (albedo / pi times the previous increment's E_indirect). The sky,
    // emission and direct light were the first pass's; no light samples, no shadow rays.
    bool incrementOnly = false;
    // Whether the light samples are projected onto SH too (projectSh): not in a bake that keeps
    // its irradiance alone (BakeRequest::irradianceOnly, the lattice search's trials).
    bool projectSh = true;
};

class RadianceSlab {
public:
    // Room for `probes` probes of `rays` rays each; forgets the previous slab. A slot's
    // results are defined once trace() ran on it (which zeroes its light-sample sums); the
    // phases below read traced slots only.
    void reset(std::size_t probes, int rays);
    // Phase 1, one slot per probe (slots are independent: any thread). Traces the probe's
    // rays from probeWorld (directions localDirs rotated by volumeRotation); with a
    // `previous` pass, hits that need E_indirect are queued for lookUp with their locality
    // key (computed here, on the tracing threads, so lookUp's sort stays a short serial step).
    void trace(std::size_t slot, const raytrace::RayScene& rs, const Scenario& sc,
               const std::vector<scene::Light>& lights, const glm::mat3& volumeRotation,
               const glm::vec3& probeWorld, const std::vector<glm::vec3>& localDirs,
               const ProbeSampler* previous, RayCounters& counters,
               const EmitterSampling& emitters = {}, std::uint64_t probeKey = 0);
    // Phase 2, once per slab after every trace: E_indirect of every queued hit, sorted by
    // the previous pass's grid cell, on `threads` threads.
    void lookUp(const ProbeSampler& previous, int threads);
    // Phase 3, one slot per probe, once: completes the slot's per-ray radiance (RGB + unused,
    // in the order of the directions) and returns it. Also for gathers that weight the rays
    // themselves (SurfaceGather.h).
    const glm::vec4* finish(std::size_t slot);
    // Phase 3 for a probe: finish, then outRgb = the 6x6 interior, RGB per texel, row-major
    // (the rays' convolution plus the emitter samples' texels).
    void convolve(std::size_t slot, const ProbeConvolution& conv, float* outRgb);
    // After convolve: the variance of each texel's luminance estimate (absolute), from the
    // sample variances of its rays (ProbeConvolution::irradianceLumaVariance) and of its
    // emitter samples. The rays are stratified, so this overestimates: NoiseRounds uses it
    // only to decide whether a second round is worth tracing.
    void texelVariance(std::size_t slot, const ProbeConvolution& conv, float* outVar) const;
    // After convolve (or finish): the slot's radiance projected onto SH L2 (9 RGB, the
    // probe's volume-local frame, probes/sh/ShIrradiance.h) by Monte Carlo over the same samples
    // the irradiance texels convolve: each ray 4 pi / N L(w) Y(w) (the ray set is uniform on
    // the sphere; L already carries the balance heuristic's weight), each emitter and
    // lit-surface sample its share c Y(w) (c: what it adds to a texel facing it, over cos).
    // conv: the pass's convolution (its rays' SH basis values).
    void projectSh(std::size_t slot, const ProbeConvolution& conv, glm::vec3* out) const;

private:
    // Zeroes the slot's emitter and lit-surface sample sums (lightRgb_ ... lightSh_).
    void zeroLightSums(std::size_t slot);
    // trace()'s lit-surface samples (EmitterSampling::litSamples).
    void traceLitSamples(std::size_t slot, const raytrace::RayScene& rs, const Scenario& sc,
                         const std::vector<scene::Light>& lights, const glm::mat3& rot,
                         const glm::vec3& origin, const EmitterSampling& nee,
                         std::uint64_t probeKey, RayCounters& counters);
    struct Pending { // a hit waiting for E_indirect
        SampleQuery query;
        // E_direct (MIS-weighted) when queued; lookUp() adds E_indirect, and finish() reads
        // the sum.
        glm::vec3 irradiance;
        glm::vec3 albedoOverPi;
        std::uint32_t ray; // slot * rays + ray index
    };
    int rays_ = 0;
    std::vector<glm::vec4> radiance_;              // per ray, slot-major: RGB + unused
    // Pending hits, `rays_` places per slot (slot-major), the first pendingCount_[slot] used;
    // keys_: the localityKey of each. Flat and on huge pages (HugePages.h): lookUp reads them
    // in key order, i.e. at random.
    HugePageVector<Pending> pending_;
    HugePageVector<std::uint32_t> keys_;
    std::vector<std::uint32_t> pendingCount_;
    // Emitter samples per slot and interior texel: RGB sum (per slot rows of the texels' R,
    // then G, then B), luminance sum and sum of squares.
    std::vector<int> slotSamples_; // emitter samples each slot's probe took (0: rays alone)
    std::vector<float> lightRgb_, lightY_, lightY2_;
    // Lit-surface samples per slot (RGB into lightRgb_), luminance sums kept apart for the
    // variance.
    std::vector<int> slotLitSamples_;
    std::vector<float> litY_, litY2_;
    // Emitter and lit-surface samples per slot projected onto SH (9 RGB each).
    std::vector<glm::vec3> lightSh_;
};

} // namespace pb::probes
