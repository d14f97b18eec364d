#pragma once
// The bake far from the origin. Embree, the bake's hit points and the sampler's lookups are
// float world coordinates: at 1e6 units a float is 1/16 apart, so hit points, shadow-ray
// offsets (1e-5 of the scene) and visibility distances lose centimetres, and a room baked
// there came out ~10% darker than the same room at the origin (`probebench stress`,
// offset=1e6). The bake therefore runs in a frame moved by bakeOrigin(): instance transforms,
// punctual lights and volume centres are shifted in double before anything is rounded to
// float, and the result's volumes are the caller's again. Scenes within 512 units of the
// origin get origin 0 and bake exactly as before. (BakeRequest::recordRays, bench_bake's
// instrumentation, then records rays in the moved frame.)
#include "probes/bake/Baker.h"

#include <glm/glm.hpp>

namespace pb::probes {

// The centre of the static geometry and the volumes, rounded to a multiple of 1024 units per
// axis (so the frame's own coordinates stay exact); 0 for scenes near the origin.
glm::dvec3 bakeOrigin(const scene::Scene& scene, const std::vector<ProbeVolume>& volumes);

// bakeProbes in the frame moved by -origin; the result is in the caller's world frame.
ProbeSet bakeProbesAround(const glm::dvec3& origin, const scene::Scene& scene,
                          const BakeRequest& request, BakeStats* stats,
                          const BakeProgressFn& progress);

} // namespace pb::probes
