#include "probes/bake/SurfaceSamples.h"

#include "probes/bake/RayDirections.h"

#include <algorithm>

namespace pb::probes {

std::vector<GatherPoint> surfaceSamples(const std::vector<raytrace::WorldTriangle>& tris, const raytrace::RayScene& rs,
                                        int count, float sealedBelow, std::uint64_t seed) {
    std::vector<GatherPoint> out;
    if (tris.empty() || count <= 0) return out;
    std::vector<double> cdf(tris.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < tris.size(); ++i)
        cdf[i] = sum += double(tris[i].area());
    const float extent = glm::length(rs.bounds().size());
    const std::vector<glm::vec3> sphere = sphericalFibonacci(32); // 16 in each hemisphere
    std::uint64_t state = seed;
    for (int attempt = 0; attempt < count * 4 && int(out.size()) < count; ++attempt) {
        const double r = double(uniformFloat(state)) * sum;
        std::size_t t = std::size_t(std::lower_bound(cdf.begin(), cdf.end(), r) - cdf.begin());
        if (t >= tris.size()) t = tris.size() - 1;
        const raytrace::WorldTriangle& w = tris[t];
        float u = uniformFloat(state), v = uniformFloat(state);
        if (u + v > 1.0f) {
            u = 1.0f - u;
            v = 1.0f - v;
        }
        glm::vec3 n = w.normal;
        if (w.doubleSided && uniformFloat(state) < 0.5f) n = -n;
        const glm::vec3 p = w.a + u * (w.b - w.a) + v * (w.c - w.a) + n * (1e-4f * extent);
        bool open = false;
        for (const glm::vec3& d : sphere) {
            if (glm::dot(d, n) <= 0.0f) continue;
            raytrace::RayHit h = rs.intersect(p, d);
            if (!h.hit() || h.t > sealedBelow) {
                open = true;
                break;
            }
        }
        if (open) out.push_back({p, n});
    }
    return out;
}

} // namespace pb::probes
