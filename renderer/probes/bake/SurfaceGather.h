#pragma once
// Irradiance gathered at surface points directly, without probes: the ground truth that a
// probe lookup at the point approximates (bench_placement's error reference).
//
// Each point traces `rays` cosine-distributed directions over the hemisphere of its normal
// (a Fibonacci spiral on the unit disk lifted to the hemisphere, twisted about the normal by
// a per-point random angle), shades every hit exactly as a bake pass does (RadiancePass.h:
// sky on a miss, 0 on the back of single-sided geometry, else emissive + albedo/pi *
// (direct + indirect)), and returns E = pi * mean(L): for cosine-distributed rays that is the
// irradiance estimator, exact for uniform radiance.
//
// indirect: the probes that carry the light of earlier bounces at the hits (E_indirect), or
// null for one bounce. A bake with B bounces reads B-1 bounce probes at its hits, so the
// gather that matches it reads a (B-1)-bounce bake: only the last bounce is gathered exactly,
// the earlier ones still come through probes (dimmed by one albedo).
#include "probes/ProbeSampler.h"
#include "raytrace/RayScene.h"
#include "probes/Scenario.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

struct GatherPoint {
    glm::vec3 pos, normal; // normal: unit, on the side to gather
};

struct GatherSettings {
    int rays = 512;
    int threads = 0; // 0 = all hardware threads
    std::uint64_t seed = 0x6A7E5EEDu;
};

// One irradiance per point (RGB, the scene's linear units); deterministic for any thread count.
std::vector<glm::vec3> gatherIrradiance(const raytrace::RayScene& rs, const Scenario& sc,
                                        const std::vector<scene::Light>& lights,
                                        const std::vector<GatherPoint>& points,
                                        const ProbeSampler* indirect, const GatherSettings& g);

// Irradiance in the air (issue 18: where dynamic objects stand, bench_placement's mid-air
// column): `rays` directions over the whole sphere (spherical Fibonacci, turned by a per-point
// random rotation) traced from each point and shaded as above; then per normal n of `normals`
// E(n) = pi * sum_r max(0, n.d_r) L_r / sum_r max(0, n.d_r) (the bake's own convolution: exact
// for uniform radiance). Result [point * normals.size() + k]; deterministic for any thread
// count.
std::vector<glm::vec3> gatherIrradianceSphere(const raytrace::RayScene& rs, const Scenario& sc,
                                              const std::vector<scene::Light>& lights,
                                              const std::vector<glm::vec3>& points,
                                              const std::vector<glm::vec3>& normals,
                                              const ProbeSampler* indirect,
                                              const GatherSettings& g);

// The local directions (z = the normal) of a gather with `rays` rays, cosine-distributed.
std::vector<glm::vec3> cosineHemisphereSpiral(int rays);

} // namespace pb::probes
