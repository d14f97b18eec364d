#include "probes/bake/BakeOrigin.h"

#include "raytrace/RayScene.h"

#include <cmath>

namespace pb::probes {

glm::dvec3 bakeOrigin(const scene::Scene& scene, const std::vector<ProbeVolume>& volumes) {
    scene::Bounds b = raytrace::staticBakeBounds(scene);
    for (const ProbeVolume& v : volumes)
        for (const glm::vec3& c : v.worldCorners())
            b.extend(c);
    if (b.empty()) return glm::dvec3(0.0);
    const glm::dvec3 centre = (glm::dvec3(b.min) + glm::dvec3(b.max)) * 0.5;
    glm::dvec3 origin(0.0);
    for (int a = 0; a < 3; ++a)
        if (std::isfinite(centre[a])) origin[a] = std::round(centre[a] / 1024.0) * 1024.0;
    return origin;
}

ProbeSet bakeProbesAround(const glm::dvec3& origin, const scene::Scene& scene,
                          const BakeRequest& request, BakeStats* stats,
                          const BakeProgressFn& progress) {
    scene::Scene local = scene;
    for (scene::Instance& inst : local.instances) {
        const glm::dvec3 t = glm::dvec3(inst.transform[3]) - origin;
        inst.transform[3] = glm::vec4(glm::vec3(t), 1.0f);
    }
    for (scene::Light& l : local.lights)
        l.position = glm::vec3(glm::dvec3(l.position) - origin);
    BakeRequest r = request;
    r.rayScene = nullptr; // built for the scene where it is, not for the moved copy
    for (ProbeVolume& v : r.volumes)
        v.center = glm::vec3(glm::dvec3(v.center) - origin);
    ProbeSet set = bakeProbes(local, r, stats, progress);
    set.volumes = request.volumes;
    set.inputHash = bakeInputHash(scene, request);
    return set;
}

} // namespace pb::probes
