#include "raytrace/SceneHash.h"

namespace pb::raytrace {

void hashSun(Hasher& h, const scene::Sun& s) {
    h.pod(std::uint8_t(s.enabled));
    h.pod(s.toSun);
    h.pod(s.color);
    h.pod(s.intensity);
}

void hashLights(Hasher& h, const std::vector<scene::Light>& lights) {
    h.pod(std::uint64_t(lights.size()));
    for (const scene::Light& l : lights) {
        h.pod(std::uint32_t(l.type));
        h.pod(l.color);
        h.pod(l.intensity);
        h.pod(l.position);
        h.pod(l.direction);
        h.pod(l.range);
        h.pod(l.innerConeAngle);
        h.pod(l.outerConeAngle);
    }
}

void hashPrimitiveGeometry(Hasher& h, const scene::Primitive& p) {
    h.pod(std::int32_t(p.material));
    h.pod(std::uint64_t(p.positions.size()));
    h.bytes(p.positions.data(), p.positions.size() * sizeof(glm::vec3));
    h.pod(std::uint64_t(p.indices.size()));
    h.bytes(p.indices.data(), p.indices.size() * sizeof(std::uint32_t));
}

} // namespace pb::raytrace
