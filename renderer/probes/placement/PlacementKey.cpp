#include "probes/placement/PlacementKey.h"

#include "probes/bake/BakeHash.h"
#include "raytrace/SceneHash.h"

namespace pb::probes {

std::uint64_t autoPlacementKey(const scene::Scene& scene, const AutoPlacementRequest& r) {
    Hasher h;
    h.pod(kAutoPlacementVersion);
    hashBakeVersionsAndScene(h, scene);
    h.pod(std::uint8_t(r.mode));
    // Every adaptive option but `threads` (it never changes the result).
    const AdaptiveOptions& a = r.adaptive;
    h.pod(a.spacing);
    h.pod(std::int32_t(a.levels));
    h.pod(std::int32_t(a.cornerRays));
    h.pod(a.nearFactor);
    h.pod(std::int32_t(a.maxChildren));
    h.pod(std::int32_t(a.pad));
    h.pod(std::uint8_t(a.lattice));
    h.pod(r.budgetBytes);
    h.pod(std::uint32_t(r.format));
    h.pod(std::int64_t(r.maxProbes));
    h.pod(std::uint8_t(r.sparse));
    if (r.sparse && r.freeSpace != FreeSpace::StandIns) h.pod(std::uint8_t(r.freeSpace) + 1);
    h.pod(std::uint8_t(r.latticeSearch));
    h.pod(std::uint8_t(r.lighting.has_value()));
    if (r.lighting) {
        h.str(r.lighting->name);
        raytrace::hashSun(h, r.lighting->sun);
        h.pod(r.lighting->sky.radiance);
    }
    h.pod(std::int32_t(r.bounces));
    return h.value();
}

} // namespace pb::probes
