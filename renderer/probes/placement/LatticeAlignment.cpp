#include "probes/placement/LatticeAlignment.h"

#include <cmath>

namespace pb::probes {

float surfaceOnProbePlanes(const ProbeVolume& v, const std::vector<raytrace::WorldTriangle>& triangles) {
    const glm::mat3 toLocal = glm::transpose(v.localToWorldRotation());
    const glm::vec3 cell = v.cellSize();
    double total = 0.0, on = 0.0;
    for (const raytrace::WorldTriangle& t : triangles) {
        const glm::vec3 centroid = v.toLocal((t.a + t.b + t.c) / 3.0f);
        if (!v.contains(v.toWorld(centroid))) continue;
        const double area = double(t.area());
        total += area;
        const glm::vec3 n = toLocal * t.normal;
        for (int a = 0; a < 3; ++a) {
            if (v.counts[a] < 2 || !(std::abs(n[a]) > 0.95f)) continue;
            const float g = (centroid[a] + v.halfExtents[a]) / cell[a];
            const float d = std::abs(g - std::round(g));
            if (d < kOnPlaneCells) on += area * double(1.0f - d / kOnPlaneCells);
        }
    }
    return total > 0.0 ? float(on / total) : 0.0f;
}

} // namespace pb::probes
