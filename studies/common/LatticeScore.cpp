#include "studies/common/LatticeScore.h"

#include "probes/bake/MidAirSamples.h"
#include "probes/bake/RayDirections.h"

#include <cmath>

namespace pb::studies {

using namespace pb::probes;

namespace {

// The surface right below p (a ray down from `above` over p), or a miss.
raytrace::RayHit surfaceBelow(const raytrace::RayScene& rs, const glm::vec3& p, float above) {
    return rs.intersect(p + glm::vec3(0, above, 0), glm::vec3(0, -1, 0));
}

// A floor seen from above: an upward face, or a double-sided face wound downward (its other
// side faces up and is rendered; Sponza's court floor, whose missing lines hid the rings of
// issue 24 from bench_lattice).
bool facesUp(const raytrace::RayScene& rs, const raytrace::RayHit& h) {
    const float y = rs.faceNormal(h.geomID, h.primID).y;
    return y > 0.99f || (y < -0.99f && rs.surface(h.geomID).doubleSided);
}

// Power of the windowed series at `frequency` (a DFT at an arbitrary frequency).
double powerAt(const std::vector<double>& x, float step, double frequency) {
    double re = 0.0, im = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double phase = 2.0 * M_PI * frequency * double(step) * double(i);
        re += x[i] * std::cos(phase);
        im -= x[i] * std::sin(phase);
    }
    return re * re + im * im;
}

} // namespace

std::vector<FloorLine> findFloorLines(const raytrace::RayScene& rs, int count, int samples, float step,
                                      std::uint64_t seed, float startBelow) {
    std::vector<FloorLine> lines;
    const scene::Bounds b = rs.bounds();
    if (b.empty() || count <= 0 || samples < 2 || !(step > 0.0f)) return lines;
    const float top = std::min(b.max.y, startBelow);
    if (!(top > b.min.y)) return lines;
    const float clearance = 4.0f * step, flat = step / 8.0f;
    const float lift = std::max(rs.epsilon() * 4.0f, 1e-4f * glm::length(b.size()));
    std::uint64_t state = seed;
    for (int attempt = 0; attempt < 4000 * count && int(lines.size()) < count; ++attempt) {
        // The axis alternates by attempt, not by line: a floor narrower than a line along one
        // axis (Sponza's courtyard along Z) must not stop the search for lines along the other.
        const glm::vec3 axis = attempt % 2 == 0 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        const glm::vec3 p(b.min.x + uniformFloat(state) * (b.max.x - b.min.x),
                          b.min.y + uniformFloat(state) * (top - b.min.y),
                          b.min.z + uniformFloat(state) * (b.max.z - b.min.z));
        // From a random height down to the first upward surface: a floor of any storey, a
        // roof, a table top; the line must then stay on it.
        const raytrace::RayHit first = rs.intersect(p, glm::vec3(0, -1, 0));
        if (!first.hit()) continue;
        const float height = p.y - first.t;
        bool ok = true;
        for (int i = 0; i < samples && ok; ++i) {
            const glm::vec3 q = glm::vec3(p.x, height, p.z) + axis * (step * float(i));
            const raytrace::RayHit h = surfaceBelow(rs, q, clearance);
            ok = h.hit() && std::fabs(h.t - clearance) <= flat && facesUp(rs, h);
            // Open above: the first thing straight up is a ceiling's front (or nothing), at
            // least the clearance away; its back would mean the point is inside a solid (a
            // floor running under a box). A double-sided face has no back.
            const raytrace::RayHit up = rs.intersect(q + glm::vec3(0, lift, 0), glm::vec3(0, 1, 0));
            ok = ok &&
                 (!up.hit() || (up.t > clearance && (rs.faceNormal(up.geomID, up.primID).y < 0.0f ||
                                                     rs.surface(up.geomID).doubleSided)));
            // A floor running under a wall box whose top is inside a ceiling box passes the
            // test above (the ceiling's underside comes first): ask every direction (the rooms).
            ok = ok && !insideGeometry(rs, q + glm::vec3(0, lift, 0), clearance);
        }
        if (!ok) continue;
        lines.push_back({glm::vec3(p.x, height + lift, p.z), axis, step, samples});
    }
    return lines;
}

double latticeScore(const std::vector<double>& residual, float step, float frequency) {
    const std::size_t n = residual.size();
    if (n < 8 || !(step > 0.0f) || !(frequency > 0.0f)) return 0.0;
    // Least-squares line through the series, removed; then the Hann window.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = double(i), y = residual[i];
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double dn = double(n), denom = dn * sxx - sx * sx;
    const double slope = denom != 0.0 ? (dn * sxy - sx * sy) / denom : 0.0;
    const double offset = (sy - slope * sx) / dn;
    std::vector<double> w(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double hann = 0.5 - 0.5 * std::cos(2.0 * M_PI * double(i) / double(n - 1));
        w[i] = (residual[i] - offset - slope * double(i)) * hann;
    }
    const double bin = 1.0 / (dn * double(step));
    double neighbours = 0.0;
    for (int k : {-3, -2, 2, 3})
        neighbours += powerAt(w, step, double(frequency) + k * bin) / 4.0;
    const double peak = powerAt(w, step, double(frequency));
    return neighbours > 0.0 ? peak / neighbours : 0.0;
}

} // namespace pb::studies
