#include "probes/bake/MidAirSamples.h"

#include "probes/bake/RayDirections.h"

#include <algorithm>

namespace pb::probes {

bool insideGeometry(const raytrace::RayScene& rs, const glm::vec3& p, float sealedBelow) {
    static const std::vector<glm::vec3> sphere = sphericalFibonacci(32);
    bool open = false;
    for (const glm::vec3& d : sphere) {
        const raytrace::RayHit h = rs.intersect(p, d);
        open = open || !h.hit() || h.t > sealedBelow;
        if (!h.hit() || rs.surface(h.geomID).doubleSided) continue;
        if (glm::dot(rs.faceNormal(h.geomID, h.primID), d) > 0.0f) return true;
    }
    return !open;
}

std::vector<glm::vec3> midAirSamples(const raytrace::RayScene& rs, const std::vector<ProbeVolume>& volumes,
                                     int count, float sealedBelow, std::uint64_t seed) {
    std::vector<glm::vec3> out;
    std::vector<const ProbeVolume*> roots;
    std::vector<double> cdf;
    double sum = 0.0;
    for (const ProbeVolume& v : volumes)
        if (v.parent.empty()) {
            roots.push_back(&v);
            cdf.push_back(sum += double(v.boxVolume()));
        }
    if (roots.empty() || count <= 0) return out;
    std::uint64_t state = seed;
    for (int attempt = 0; attempt < count * 8 && int(out.size()) < count; ++attempt) {
        const double r = double(uniformFloat(state)) * sum;
        std::size_t i = std::size_t(std::lower_bound(cdf.begin(), cdf.end(), r) - cdf.begin());
        const ProbeVolume& v = *roots[std::min(i, roots.size() - 1)];
        glm::vec3 local;
        for (int a = 0; a < 3; ++a)
            local[a] = (2.0f * uniformFloat(state) - 1.0f) * v.halfExtents[a];
        const glm::vec3 p = v.toWorld(local);
        if (!insideGeometry(rs, p, sealedBelow)) out.push_back(p);
    }
    return out;
}

} // namespace pb::probes
