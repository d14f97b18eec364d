#pragma once
// The scene's emissive triangles as lights the bake can sample directly (next-event
// estimation), picked in proportion to their power with an alias table.
//
// Why: a probe finds a small emissive panel only when one of its few hundred rays happens to
// hit it, so a scene lit by emitters (the built-in Cornell box: a 0.6 m panel) bakes with
// tens of percent of noise. Sampling points on the emitters themselves, weighted against the
// probe rays by multiple importance sampling (RadiancePass.h), removes most of it.
//
// Power of triangle k: luminance(emitted radiance) x area (x 2 when double-sided, since it
// emits from both faces). Sampling k then a uniform point on it has the area density
//     pdfArea(k) = P(k) / area(k),   P(k) = power(k) / sum of powers,
// and in solid angle, seen from x at distance d under the emitter's cosine cos_l:
//     pdf(omega) = pdfArea(k) * d^2 / |cos_l|.
// Deterministic: the same scene gives the same table; sampling is a pure function of its
// three uniforms.
#include "raytrace/AliasTable.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace pb::raytrace {

struct EmissiveTriangle {
    glm::vec3 a, b, c;
    glm::vec3 normal;   // unit, front side
    glm::vec3 radiance; // emitted, from the front (and the back when doubleSided)
    bool doubleSided = false;
    float area = 0.0f;
    unsigned geomID = 0, primID = 0; // the RayScene triangle it is
};

struct EmitterSample {
    glm::vec3 point;
    int triangle = -1;
    float pdfArea = 0.0f; // P(k) / area(k)
};

class EmitterTable {
public:
    EmitterTable() = default;
    // Triangles with no area or no emitted luminance are left out.
    explicit EmitterTable(std::vector<EmissiveTriangle> triangles);

    bool empty() const { return triangles_.empty(); }
    std::size_t size() const { return triangles_.size(); }
    const EmissiveTriangle& triangle(int k) const { return triangles_[std::size_t(k)]; }
    // Index of the RayScene triangle (geomID, primID) in this table, or -1.
    int find(unsigned geomID, unsigned primID) const;
    // P(k) / area(k) of table triangle k.
    float pdfArea(int k) const { return pdfArea_[std::size_t(k)]; }

    // u0 picks the triangle (alias table), u1, u2 the point (uniform on the triangle).
    EmitterSample sample(float u0, float u1, float u2) const;

private:
    std::vector<EmissiveTriangle> triangles_;
    std::vector<float> pdfArea_;
    AliasTable alias_; // by power
    std::vector<std::vector<int>> indexOfPrim_; // [geomID][primID] -> table index or -1
};

} // namespace pb::raytrace
