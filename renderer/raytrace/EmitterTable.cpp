#include "raytrace/EmitterTable.h"

#include "core/Luminance.h"

#include <cmath>

namespace pb::raytrace {

EmitterTable::EmitterTable(std::vector<EmissiveTriangle> all) {
    std::vector<double> power;
    for (EmissiveTriangle& t : all) {
        t.area = 0.5f * glm::length(glm::cross(t.b - t.a, t.c - t.a));
        const double p = double(luminance(t.radiance)) * t.area * (t.doubleSided ? 2.0 : 1.0);
        if (!(p > 0.0) || !std::isfinite(p)) continue;
        triangles_.push_back(t);
        power.push_back(p);
    }
    const std::size_t n = triangles_.size();
    if (n == 0) return;
    alias_ = AliasTable(power);
    pdfArea_.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        pdfArea_[k] = float(alias_.probability(k) / double(triangles_[k].area));

    for (std::size_t k = 0; k < n; ++k) {
        const EmissiveTriangle& t = triangles_[k];
        if (indexOfPrim_.size() <= t.geomID) indexOfPrim_.resize(t.geomID + 1);
        std::vector<int>& prims = indexOfPrim_[t.geomID];
        if (prims.size() <= t.primID) prims.resize(t.primID + 1, -1);
        prims[t.primID] = int(k);
    }
}

int EmitterTable::find(unsigned geomID, unsigned primID) const {
    if (geomID >= indexOfPrim_.size()) return -1;
    const std::vector<int>& prims = indexOfPrim_[geomID];
    return primID < prims.size() ? prims[primID] : -1;
}

EmitterSample EmitterTable::sample(float u0, float u1, float u2) const {
    EmitterSample s;
    if (triangles_.empty()) return s;
    const std::size_t k = alias_.pick(u0);
    const EmissiveTriangle& t = triangles_[k];
    // Uniform on the triangle: the square-root warp of two uniforms.
    const float r = std::sqrt(u1);
    s.point = t.a * (1.0f - r) + t.b * (r * (1.0f - u2)) + t.c * (r * u2);
    s.triangle = int(k);
    s.pdfArea = pdfArea_[k];
    return s;
}

} // namespace pb::raytrace
