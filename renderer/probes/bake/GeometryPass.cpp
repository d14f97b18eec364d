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

// The offsets a probe may take: +-kMaxRelocation cell per local axis, and for a child volume
// never out of its box. A child's probe on the box's face belongs to the inside: moved
// outwards it would light the inside with what lies beyond the face. The case that showed it
// (issue 24): a room volume ending in the middle of a 5 cm partition; its probes there sit
// inside the wall, and "through the nearest back face" is a coin toss between the two sides,
// so half of them went to the lit room next door and leaked its light along the dark room's
// corner. Roots keep the plain clamp: their faces lie on or beyond the scene's bounds, and
// bounding them too made the default placement's mean error on the Cornell box 3.3% worse
// (bench_placement; studies/findings/lattice-on-floors.md "Lattice on floors").
struct OffsetBounds {
    glm::vec3 lo, hi;
    // Whether a step along local direction d can move the probe at all (not straight out).
    bool allows(const glm::vec3& d) const {
        for (int a = 0; a < 3; ++a)
            if ((d[a] < 0.0f && lo[a] == 0.0f) || (d[a] > 0.0f && hi[a] == 0.0f)) return false;
        return true;
    }
};

OffsetBounds offsetBounds(const ProbeVolume& vol, const glm::ivec3& c) {
    const glm::vec3 limit = kMaxRelocation * vol.cellSize();
    OffsetBounds b{-limit, limit};
    if (vol.parent.empty()) return b;
    for (int a = 0; a < 3; ++a) {
        if (vol.counts[a] < 2) continue; // a single probe on an axis sits mid-box, on no face
        if (c[a] == 0) b.lo[a] = 0.0f;
        if (c[a] == vol.counts[a] - 1) b.hi[a] = 0.0f;
    }
    return b;
}

TraceSummary trace(const raytrace::RayScene& rs, const glm::vec3& origin, const glm::mat3& rot,
                   const std::vector<glm::vec3>& dirs, const OffsetBounds& bounds,
                   GeometryScratch& s, std::uint64_t& rays) {
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
        const raytrace::RayHit& h = s.hits[size_t(r)];
        s.t[size_t(r)] = h.hit() ? h.t : std::numeric_limits<float>::infinity();
        s.backface[size_t(r)] = 0;
        if (!h.hit()) continue;
        // Double-sided first: it spares the face normal's cache miss (same result).
        bool back = !rs.surface(h.geomID).doubleSided &&
                    glm::dot(rs.faceNormal(h.geomID, h.primID), s.worldDirs[size_t(r)]) > 0.0f;
        if (back) {
            s.backface[size_t(r)] = 1;
            ++sum.backfaces;
            // The way out is the nearest back face the probe may step through (OffsetBounds).
            if (h.t < sum.closestBack && bounds.allows(dirs[size_t(r)]))
                sum.closestBack = h.t, sum.closestBackRay = r;
        } else if (h.t < sum.closestFront) {
            sum.closestFront = h.t, sum.closestFrontRay = r;
        }
    }
    return sum;
}

} // namespace

void bakeProbeGeometry(const raytrace::RayScene& rs, const ProbeVolume& vol, const glm::ivec3& c,
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
    const OffsetBounds bounds = offsetBounds(vol, c);
    const float clearance = kRelocationClearance * vol.minCellSize();
    const float threshold = settings.backfaceThreshold * float(n);

    glm::vec3 offset(0.0f);
    TraceSummary sum = trace(rs, vol.toWorld(grid), rot, dirs, bounds, s, rays);
    state.insideAtLattice = float(sum.backfaces) > threshold;
    for (int it = 0; settings.relocate && it < kMaxRelocationIterations; ++it) {
        glm::vec3 move(0.0f);
        if (float(sum.backfaces) > threshold && sum.closestBackRay >= 0)
            move = dirs[size_t(sum.closestBackRay)] * (sum.closestBack + clearance);
        else if (sum.closestFront < clearance && sum.closestFrontRay >= 0)
            move = -dirs[size_t(sum.closestFrontRay)] * (clearance - sum.closestFront);
        glm::vec3 next = glm::clamp(offset + move, bounds.lo, bounds.hi);
        if (next == offset) break;
        offset = next;
        sum = trace(rs, vol.toWorld(grid + offset), rot, dirs, bounds, s, rays);
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
