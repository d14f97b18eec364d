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
#include "probes/bake/ProbeConvolution.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/RayScene.h"
#include "probes/Scenario.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

struct RayCounters {
    std::uint64_t primary = 0, shadow = 0;
};

class RadianceSlab {
public:
    // Room for `probes` probes of `rays` rays each; forgets the previous slab.
    void reset(std::size_t probes, int rays);
    // Phase 1, one slot per probe (slots are independent: any thread). Traces the probe's
    // rays from probeWorld (directions localDirs rotated by volumeRotation); with a
    // `previous` pass, hits that need E_indirect are queued for lookUp with their locality
    // key (computed here, on the tracing threads, so lookUp's sort stays a short serial step).
    void trace(std::size_t slot, const RayScene& rs, const Scenario& sc,
               const std::vector<scene::Light>& lights, const glm::mat3& volumeRotation,
               const glm::vec3& probeWorld, const std::vector<glm::vec3>& localDirs,
               const ProbeSampler* previous, RayCounters& counters);
    // Phase 2, once per slab after every trace: E_indirect of every queued hit, sorted by
    // the previous pass's grid cell, on `threads` threads.
    void lookUp(const ProbeSampler& previous, int threads);
    // Phase 3, one slot per probe, once: completes the slot's per-ray radiance (RGB + unused,
    // in the order of the directions) and returns it. Also for gathers that weight the rays
    // themselves (SurfaceGather.h).
    const glm::vec4* finish(std::size_t slot);
    // Phase 3 for a probe: finish, then outRgb = the 6x6 interior, RGB per texel, row-major.
    void convolve(std::size_t slot, const ProbeConvolution& conv, float* outRgb);

private:
    struct Pending { // a hit waiting for E_indirect
        SampleQuery query;
        glm::vec3 direct, albedoOverPi;
        std::uint32_t ray; // slot * rays + ray index
    };
    int rays_ = 0;
    std::vector<RayHit> hits_;                     // per ray, slot-major
    std::vector<glm::vec4> radiance_;              // per ray, slot-major: RGB + unused
    std::vector<std::vector<Pending>> pending_;    // per slot
    std::vector<std::vector<std::uint32_t>> keys_; // per slot: localityKey of each pending hit
    std::vector<glm::vec3> indirect_;              // E_indirect per ray (pending hits only)
};

} // namespace pb::probes
