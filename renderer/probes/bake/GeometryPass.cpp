#include "probes/bake/GeometryPass.h"

#include <cmath>
#include <limits>

namespace pb::probes {
namespace {

struct TraceSummary {
    int backfaces = 0;
    float closestBack = std::numeric_limits<float>::infinity();
    float closestFront = std::numeric_limits<float>::infinity();
    int closestBackRay = -1, closestFrontRay = -1;
};

TraceSummary trace(const RayScene& rs, const glm::vec3& origin, const glm::mat3& rot,
                   const std::vector<glm::vec3>& dirs, GeometryScratch& s, std::uint64_t& rays) {
    TraceSummary sum;
    const int n = int(dirs.size());
    // All rays first, then the classification: the face normal of each hit is prefetched
    // while the following rays are traced (as RadianceSlab::trace; same results, same order).
    for (int r = 0; r < n; ++r) {
        s.worldDirs[size_t(r)] = rot * dirs[size_t(r)];
        s.hits[size_t(r)] = rs.intersect(origin, s.worldDirs[size_t(r)]);
        rs.prefetchSurface(s.hits[size_t(r)]);
    }
    rays += std::uint64_t(n);
    for (int r = 0; r < n; ++r) {
        const RayHit& h = s.hits[size_t(r)];
        s.t[size_t(r)] = h.hit() ? h.t : std::numeric_limits<float>::infinity();
        s.backface[size_t(r)] = 0;
        if (!h.hit()) continue;
        // Double-sided first: it spares the face normal's cache miss (same result).
        bool back = !rs.surface(h.geomID).doubleSided &&
                    glm::dot(rs.faceNormal(h.geomID, h.primID), s.worldDirs[size_t(r)]) > 0.0f;
        if (back) {
            s.backface[size_t(r)] = 1;
            ++sum.backfaces;
            if (h.t < sum.closestBack) sum.closestBack = h.t, sum.closestBackRay = r;
        } else if (h.t < sum.closestFront) {
            sum.closestFront = h.t, sum.closestFrontRay = r;
        }
    }
    return sum;
}

} // namespace

void bakeProbeGeometry(const RayScene& rs, const ProbeVolume& vol, const glm::ivec3& c,
                       const std::vector<glm::vec3>& dirs, const ProbeConvolution& conv,
                       const BakeSettings& settings, GeometryScratch& s, ProbeState& state,
                       float* visOut, std::uint64_t& rays) {
    const int n = int(dirs.size());
    s.hits.resize(size_t(n));
    s.worldDirs.resize(size_t(n));
    s.t.resize(size_t(n));
    s.backface.resize(size_t(n));
    s.dist01.resize(size_t(n));
    const glm::mat3 rot = vol.localToWorldRotation();
    const glm::vec3 grid = vol.gridLocal(c);
    const glm::vec3 limit = kMaxRelocation * vol.cellSize();
    const float clearance = kRelocationClearance * vol.minCellSize();
    const float threshold = settings.backfaceThreshold * float(n);

    glm::vec3 offset(0.0f);
    TraceSummary sum = trace(rs, vol.toWorld(grid), rot, dirs, s, rays);
    state.insideAtLattice = float(sum.backfaces) > threshold;
    for (int it = 0; settings.relocate && it < kMaxRelocationIterations; ++it) {
        glm::vec3 move(0.0f);
        if (float(sum.backfaces) > threshold && sum.closestBackRay >= 0)
            move = dirs[size_t(sum.closestBackRay)] * (sum.closestBack + clearance);
        else if (sum.closestFront < clearance && sum.closestFrontRay >= 0)
            move = -dirs[size_t(sum.closestFrontRay)] * (clearance - sum.closestFront);
        glm::vec3 next = glm::clamp(offset + move, -limit, limit);
        if (next == offset) break;
        offset = next;
        sum = trace(rs, vol.toWorld(grid + offset), rot, dirs, s, rays);
    }

    state.offset = offset;
    state.backfaceRatio = n > 0 ? float(sum.backfaces) / float(n) : 0.0f;
    state.valid = !(float(sum.backfaces) > threshold);
    if (!state.valid) return;
    const float maxDist = vol.maxDistance();
    for (int r = 0; r < n; ++r)
        s.dist01[size_t(r)] = std::min(s.t[size_t(r)], maxDist) / maxDist;
    conv.visibility(s.dist01.data(), visOut);
}

} // namespace pb::probes
