#include "probes/placement/AutoVolume.h"

#include "core/Error.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pb::probes {
namespace {

// One axis of the fit: probe count, half extent and a shift of the centre, for a (grown)
// size, a spacing and the lattice's finest subdivision (2^-subdivisions of a cell).
struct Axis {
    int count;
    float half;
    float shift = 0.0f;
};

Axis axisFor(float size, float spacing, AutoLattice lattice, int subdivisions) {
    if (lattice == AutoLattice::FitBounds) { // planes on the box; a thin axis widened
        const float s = std::max(size, spacing);
        const double cells = std::max(1.0, std::ceil(double(s) / double(spacing) - 1e-6));
        return {int(std::min(cells + 1.0, double(kMaxProbesPerAxis))), 0.5f * s};
    }
    // HalfCellMargin: the box is the size plus one finest cell (f = cell * frac), half of it
    // beyond each face, so the faces lie mid-way between two planes of every subdivision.
    const double frac = std::ldexp(1.0, -subdivisions);
    if (size < 0.5f * spacing) {
        // A flat axis: one cell of `spacing` around it; off-centre by half a finest cell when
        // subdivided (a subdivision's middle plane would lie on it).
        return {2, 0.5f * spacing, subdivisions > 0 ? float(0.5 * frac * spacing) : 0.0f};
    }
    double cells = std::ceil(double(size) / double(spacing) + frac - 1e-6);
    cells = std::min(cells, double(kMaxProbesPerAxis - 1));
    const double cell = double(size) / (cells - frac);
    return {int(cells) + 1, float(0.5 * (double(size) + cell * frac))};
}

glm::ivec3 countsFor(const glm::vec3& size, float spacing, AutoLattice lattice, int subdivisions) {
    return {axisFor(size.x, spacing, lattice, subdivisions).count,
            axisFor(size.y, spacing, lattice, subdivisions).count,
            axisFor(size.z, spacing, lattice, subdivisions).count};
}

long long product(const glm::ivec3& c) {
    return (long long)c.x * c.y * c.z;
}

} // namespace

AutoVolume fitAutoVolume(const scene::Bounds& b, float spacing, long long maxProbes,
                         AutoLattice lattice, int subdivisions) {
    if (b.empty())
        throw Error("--volumes auto: the scene has no static geometry to fit a volume to "
                    "(give --volumes FILE.toml)");
    glm::vec3 size = b.size();
    float extent = std::max(size.x, std::max(size.y, size.z));
    if (!(extent > 0.0f) || !std::isfinite(extent))
        throw Error("--volumes auto: the scene's static geometry has no extent");
    size += glm::vec3(2e-3f * extent);
    float requested = spacing;
    if (!(requested > 0.0f)) {
        // About kAutoTargetProbes probes, counting thin axes (widened to one spacing) right.
        requested = float(std::cbrt(double(size.x) * size.y * size.z / kAutoTargetProbes));
        for (int it = 0; it < 16; ++it) {
            glm::vec3 s = glm::max(size, glm::vec3(requested));
            requested = float(std::cbrt(double(s.x) * s.y * s.z / kAutoTargetProbes));
        }
    }
    spacing = std::max(requested, extent / float(kMaxProbesPerAxis - 1));
    while (product(countsFor(size, spacing, lattice, subdivisions)) > maxProbes)
        spacing *= 1.01f;

    AutoVolume out;
    if (spacing != requested) {
        const double wanted = double(product(countsFor(size, requested, lattice, subdivisions)));
        std::ostringstream s;
        s << "--volumes auto: spacing " << requested << " would need " << std::fixed
          << std::setprecision(0) << wanted << std::defaultfloat << " probes; using spacing "
          << spacing << " (" << product(countsFor(size, spacing, lattice, subdivisions))
          << " probes, the limit is " << maxProbes << ")";
        out.note = s.str();
    }
    out.spacing = spacing;
    out.volume.name = "auto";
    out.volume.center = b.center();
    for (int a = 0; a < 3; ++a) {
        const Axis axis = axisFor(size[a], spacing, lattice, subdivisions);
        out.volume.counts[a] = axis.count;
        out.volume.halfExtents[a] = axis.half;
        out.volume.center[a] += axis.shift;
    }
    return out;
}

} // namespace pb::probes
