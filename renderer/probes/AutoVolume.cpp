#include "probes/AutoVolume.h"

#include "core/Error.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pb::probes {
namespace {

glm::ivec3 countsFor(const glm::vec3& size, float spacing) {
    glm::ivec3 c;
    for (int a = 0; a < 3; ++a) {
        double n = std::ceil(double(size[a]) / double(spacing) - 1e-6) + 1.0;
        c[a] = int(std::min(std::max(n, 2.0), double(kMaxProbesPerAxis)));
    }
    return c;
}

long long product(const glm::ivec3& c) {
    return (long long)c.x * c.y * c.z;
}

} // namespace

AutoVolume fitAutoVolume(const scene::Bounds& b, float spacing, long long maxProbes) {
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
    while (product(countsFor(glm::max(size, glm::vec3(spacing)), spacing)) > maxProbes)
        spacing *= 1.01f;

    AutoVolume out;
    if (spacing != requested) {
        double wanted = 1.0;
        for (int a = 0; a < 3; ++a)
            wanted *= std::ceil(double(std::max(size[a], requested)) / requested) + 1.0;
        std::ostringstream s;
        s << "--volumes auto: spacing " << requested << " would need " << std::fixed
          << std::setprecision(0) << wanted << std::defaultfloat << " probes; using spacing "
          << spacing << " (" << product(countsFor(glm::max(size, glm::vec3(spacing)), spacing))
          << " probes, the limit is " << maxProbes << ")";
        out.note = s.str();
    }
    size = glm::max(size, glm::vec3(spacing));
    out.spacing = spacing;
    out.volume.name = "auto";
    out.volume.center = b.center();
    out.volume.halfExtents = size * 0.5f;
    out.volume.counts = countsFor(size, spacing);
    return out;
}

} // namespace pb::probes
