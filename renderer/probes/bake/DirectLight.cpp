#include "probes/bake/DirectLight.h"

#include <cmath>
#include <limits>

namespace pb::probes {

glm::vec3 directIrradiance(const raytrace::RayScene& rs, const Scenario& sc,
                           const std::vector<scene::Light>& lights, const glm::vec3& x,
                           const glm::vec3& n, std::uint64_t& shadowRays) {
    const float eps = rs.epsilon();
    const glm::vec3 origin = x + n * eps;
    const float inf = std::numeric_limits<float>::infinity();
    glm::vec3 e(0.0f);

    if (sc.sun.enabled && sc.sun.intensity > 0.0f) {
        float c = glm::dot(n, sc.sun.toSun);
        if (c > 0.0f) {
            ++shadowRays;
            if (!rs.occluded(origin, sc.sun.toSun, 0.0f, inf))
                e += sc.sun.color * (sc.sun.intensity * c);
        }
    }
    for (const scene::Light& l : lights) {
        if (!(l.intensity > 0.0f)) continue;
        if (l.type == scene::LightType::Directional) {
            glm::vec3 toLight = -glm::normalize(l.direction);
            float c = glm::dot(n, toLight);
            if (c <= 0.0f) continue;
            ++shadowRays;
            if (!rs.occluded(origin, toLight, 0.0f, inf)) e += l.color * (l.intensity * c);
            continue;
        }
        glm::vec3 toLight = l.position - x;
        float d2 = glm::dot(toLight, toLight);
        if (!(d2 > 1e-12f)) continue;
        float d = std::sqrt(d2);
        glm::vec3 L = toLight / d;
        float c = glm::dot(n, L);
        if (c <= 0.0f) continue;
        float att = 1.0f / d2;
        if (l.range > 0.0f) {
            float r = d / l.range, r4 = r * r * r * r;
            float w = std::min(std::max(1.0f - r4, 0.0f), 1.0f);
            att *= w * w;
        }
        if (l.type == scene::LightType::Spot) {
            float cosOuter = std::cos(l.outerConeAngle), cosInner = std::cos(l.innerConeAngle);
            float scale = 1.0f / std::max(1e-3f, cosInner - cosOuter);
            float offset = -cosOuter * scale;
            float cd = glm::dot(glm::normalize(l.direction), -L);
            float a = std::min(std::max(cd * scale + offset, 0.0f), 1.0f);
            att *= a * a;
        }
        if (!(att > 0.0f)) continue; // also drops NaN from a degenerate spot direction
        ++shadowRays;
        if (!rs.occluded(origin, toLight, 0.0f, 1.0f - 2.0f * eps / std::max(d, eps)))
            e += l.color * (l.intensity * c * att);
    }
    return e;
}

} // namespace pb::probes
