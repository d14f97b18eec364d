#pragma once
// Direct irradiance at a bake hit point: the scenario's sun and the scene's punctual lights,
// each with a shadow ray. Units follow Scene.h: the sun's intensity is the irradiance on a
// surface facing it; directional lights give lux, point/spot lights candela, so
//     E_sun   = colour * intensity * max(0, n.l)
//     E_point = colour * intensity * max(0, n.l) / d^2 * window(d)
//     E_spot  = E_point * the glTF cone factor clamp(cd*scale + offset, 0, 1)^2
// with glTF KHR_lights_punctual's range window clamp(1 - (d/range)^4, 0, 1)^2 (range > 0)
// and scale = 1 / max(1e-3, cos(inner) - cos(outer)), offset = -cos(outer) * scale.
#include "raytrace/RayScene.h"
#include "probes/Scenario.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// x: hit point; n: unit normal on the side the ray arrived from. shadowRays is incremented
// per shadow ray traced.
glm::vec3 directIrradiance(const raytrace::RayScene& rs, const Scenario& sc,
                           const std::vector<scene::Light>& lights, const glm::vec3& x,
                           const glm::vec3& n, std::uint64_t& shadowRays);

} // namespace pb::probes
