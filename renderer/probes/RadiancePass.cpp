#include "probes/RadiancePass.h"

#include "probes/DirectLight.h"

#include <cmath>

namespace pb::probes {

void bakeProbeRadiance(const RayScene& rs, const Scenario& sc,
                       const std::vector<scene::Light>& lights, const glm::mat3& rot,
                       const glm::vec3& origin, const std::vector<glm::vec3>& dirs,
                       const ProbeConvolution& conv, const ProbeSampler* previous,
                       RadianceScratch& s, float* outRgb, RayCounters& counters) {
    const std::size_t n = dirs.size();
    s.r.resize(n);
    s.g.resize(n);
    s.b.resize(n);
    const float invPi = float(1.0 / M_PI);
    SampleOptions noFade;
    noFade.edgeFade = false;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d = rot * dirs[i];
        RayHit h = rs.intersect(origin, d);
        ++counters.primary;
        glm::vec3 L;
        if (!h.hit()) {
            L = sc.sky.radiance;
        } else {
            const SurfaceInfo& surf = rs.surface(h.geomID);
            glm::vec3 nrm = rs.faceNormal(h.geomID, h.primID);
            bool back = glm::dot(nrm, d) > 0.0f;
            if (back && !surf.doubleSided) {
                L = glm::vec3(0.0f);
            } else {
                if (back) nrm = -nrm;
                L = surf.emissive;
                if (surf.albedo != glm::vec3(0.0f)) {
                    const glm::vec3 x = origin + d * h.t;
                    glm::vec3 e = directIrradiance(rs, sc, lights, x, nrm, counters.shadow);
                    if (previous) e += previous->sample(x, nrm, -d, noFade).irradiance;
                    L += surf.albedo * invPi * e;
                }
            }
        }
        s.r[i] = L.x;
        s.g[i] = L.y;
        s.b[i] = L.z;
    }
    conv.irradiance(s.r.data(), s.g.data(), s.b.data(), outRgb);
}

} // namespace pb::probes
