#include "probes/bake/LitSurfaces.h"

#include "core/Luminance.h"
#include "core/ParallelFor.h"
#include "raytrace/AliasTable.h"
#include "probes/bake/DirectLight.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {

namespace {

// Corner k (0..2) of sub-triangle `sub` of an n-split triangle, in barycentrics (u, v) of the
// triangle's corners b and c, scaled by n. Lower (i, j): (i, j), (i+1, j), (i, j+1); upper:
// (i+1, j), (i+1, j+1), (i, j+1).
glm::vec2 subCorner(int i, int j, bool upper, int k) {
    static const int lower[3][2] = {{0, 0}, {1, 0}, {0, 1}}, up[3][2] = {{1, 0}, {1, 1}, {0, 1}};
    const int(*c)[2] = upper ? up : lower;
    return {float(i + c[k][0]), float(j + c[k][1])};
}

} // namespace

LitSurfaces::LitSurfaces(const raytrace::RayScene& rs, const Scenario& sc,
                         const std::vector<scene::Light>& lights, int threads,
                         std::uint64_t& shadowRays)
    : rs_(&rs) {
    const glm::vec3 size = rs.bounds().size();
    const float extent = std::max(size.x, std::max(size.y, size.z));
    const float patchEdge = extent > 0.0f ? extent / kPatchesPerExtent : 1.0f;
    const bool anyLight = (sc.sun.enabled && sc.sun.intensity > 0.0f) || !lights.empty();
    if (!anyLight) return;

    // 1. The reflecting triangles' splits and their patch sides' places ("candidates": every
    //    side of every patch, numbered triangle by triangle). The candidates themselves are
    //    enumerated again where they are needed (forEachPatchSide) instead of stored: on the
    //    decimated Sponza they were 818,058 of 76 bytes, whose fresh pages cost more CPU to
    //    fault and clear than enumerating them twice.
    geometryFirst_.assign(rs.geometryCount() + 1, 0);
    for (unsigned g = 0; g < rs.geometryCount(); ++g)
        geometryFirst_[g + 1] = geometryFirst_[g] + rs.triangleCount(g);
    triangles_.assign(geometryFirst_.back(), TriangleSlots{});
    struct Reflecting {
        unsigned geomID, primID;
        std::size_t firstCandidate;
    };
    std::vector<Reflecting> reflecting;
    std::size_t slotCount = 0, candidateCount = 0;
    for (unsigned g = 0; g < rs.geometryCount(); ++g) {
        const raytrace::SurfaceInfo& surf = rs.surface(g);
        if (surf.albedo == glm::vec3(0.0f)) continue;
        for (unsigned p = 0; p < rs.triangleCount(g); ++p) {
            glm::vec3 a, b, c;
            rs.triangleCorners(g, p, a, b, c);
            const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
            if (!(area > 0.0f)) continue;
            const float edge = std::max(glm::length(b - a),
                                        std::max(glm::length(c - b), glm::length(a - c)));
            const int n = std::clamp(int(std::ceil(edge / patchEdge)), 1, kMaxSplit);
            // Its slots come in step 3, if any of its patches is lit.
            triangles_[geometryFirst_[g] + p].split = n;
            reflecting.push_back({g, p, candidateCount});
            candidateCount += std::size_t(n * n * (surf.doubleSided ? 2 : 1));
        }
    }
    patches_ = candidateCount;
    // Calls visit(k, corners, normal, albedoOverPi, subArea, slot) for candidate k = the
    // triangle's first + 0, 1, ... in order: sub-triangle (i, j, lower then upper), then side.
    auto forEachPatchSide = [&](const Reflecting& r, auto&& visit) {
        const unsigned g = r.geomID, p = r.primID;
        const raytrace::SurfaceInfo& surf = rs.surface(g);
        const glm::vec3 albedoOverPi = surf.albedo * float(1.0 / M_PI);
        const int n = triangles_[geometryFirst_[g] + p].split;
        glm::vec3 a, b, c;
        rs.triangleCorners(g, p, a, b, c);
        const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
        const glm::vec3 nrm = rs.faceNormal(g, p);
        const float subArea = area / float(n * n);
        std::size_t k = r.firstCandidate;
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j)
                for (int upper = 0; upper < 2; ++upper) {
                    if (upper && i + j > n - 2) continue;
                    glm::vec3 corner[3];
                    for (int q = 0; q < 3; ++q) {
                        const glm::vec2 uv = subCorner(i, j, upper != 0, q) / float(n);
                        corner[q] = a + uv.x * (b - a) + uv.y * (c - a);
                    }
                    for (int side = 0; side < (surf.doubleSided ? 2 : 1); ++side)
                        visit(k++, corner, side ? -nrm : nrm, albedoOverPi, subArea,
                              ((i * n + j) * 2 + upper) * 2 + side);
                }
    };

    // 2. Their power, from the direct light at the patch centre (shadow rays: all threads).
    HugePageVector<double> power(candidateCount);
    std::vector<PerThread<std::uint64_t>> rays(std::size_t(std::max(threads, 1)));
    parallelFor(reflecting.size(), threads, [&](std::size_t r, int t) {
        forEachPatchSide(reflecting[r], [&](std::size_t k, const glm::vec3* corner,
                                            const glm::vec3& normal, const glm::vec3& albedoOverPi,
                                            float subArea, int) {
            const glm::vec3 centre = (corner[0] + corner[1] + corner[2]) / 3.0f;
            const glm::vec3 e =
                directIrradiance(rs, sc, lights, centre, normal, rays[size_t(t)].value);
            power[k] = double(luminance(albedoOverPi * e)) * double(subArea);
        });
    });
    for (const PerThread<std::uint64_t>& r : rays)
        shadowRays += r.value;

    // 3. The lit ones become entries, in candidate order (deterministic). Only a triangle
    //    with a lit patch side has slots: a hit on any other one reads no density (slot -1,
    //    density 0, as its slots' would be), and the density array the shading reads at random
    //    holds lit triangles only (on the decimated Sponza 1.6M slots were 95% zeros).
    litTriangles_.assign((triangles_.size() + 63) / 64, 0);
    for (const Reflecting& r : reflecting) {
        const std::size_t index = geometryFirst_[r.geomID] + r.primID;
        TriangleSlots& t = triangles_[index];
        const std::size_t sides = rs.surface(r.geomID).doubleSided ? 2 : 1;
        const std::size_t end = r.firstCandidate + std::size_t(t.split * t.split) * sides;
        for (std::size_t k = r.firstCandidate; k < end; ++k)
            if (power[k] > 0.0 && std::isfinite(power[k])) {
                t.first = std::int32_t(slotCount);
                slotCount += std::size_t(t.split * t.split * 4);
                litTriangles_[index >> 6] |= std::uint64_t(1) << (index & 63);
                break;
            }
    }
    std::vector<std::int32_t> slots(slotCount, -1); // entry index or -1
    std::vector<double> weights;
    std::size_t litCount = 0; // reserved up front: each growth of a huge-page array copies it
    for (double w : power)
        litCount += w > 0.0 && std::isfinite(w);
    entries_.reserve(litCount);
    sides_.reserve(litCount);
    weights.reserve(litCount);
    for (const Reflecting& r : reflecting)
        forEachPatchSide(r, [&](std::size_t k, const glm::vec3* corner, const glm::vec3& normal,
                                const glm::vec3& albedoOverPi, float, int slot) {
            if (!(power[k] > 0.0) || !std::isfinite(power[k])) return;
            slots[std::size_t(slotsOf(r.geomID, r.primID)->first + slot)] =
                std::int32_t(entries_.size());
            entries_.push_back({corner[0], corner[1], corner[2], normal, albedoOverPi, 0.0f});
            sides_.push_back({r.geomID, r.primID, (slot & 1) != 0});
            weights.push_back(power[k]);
        });
    raytrace::AliasTable table(weights);
    if (table.empty()) {
        entries_.clear();
        sides_.clear();
        litTriangles_.clear();
        return;
    }
    for (std::size_t e = 0; e < entries_.size(); ++e) {
        const Entry& en = entries_[e];
        const float area = 0.5f * glm::length(glm::cross(en.b - en.a, en.c - en.a));
        entries_[e].pdfArea = float(table.probability(e) / double(area));
    }
    slotPdf_.assign(slotCount, 0.0f);
    for (std::size_t k = 0; k < slotCount; ++k)
        if (slots[k] >= 0) slotPdf_[k] = entries_[std::size_t(slots[k])].pdfArea;
    pick_ = std::move(table);
}

std::int64_t LitSurfaces::slotOf(unsigned geomID, unsigned primID, bool back,
                                 const glm::vec3& x) const {
    if (!litSlotsOf(geomID, primID)) return -1;
    glm::vec3 a, b, c;
    rs_->triangleCorners(geomID, primID, a, b, c);
    // Barycentrics of x: u for corner b, v for corner c.
    const glm::vec3 e0 = b - a, e1 = c - a, d = x - a;
    const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const float d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
    const float denom = d00 * d11 - d01 * d01;
    if (!(denom > 0.0f)) return -1;
    const float u = (d11 * d20 - d01 * d21) / denom, v = (d00 * d21 - d01 * d20) / denom;
    return slotOfBarycentric(geomID, primID, back, u, v);
}

LitPatchSample LitSurfaces::sampleEntry(std::size_t k, float u1, float u2) const {
    LitPatchSample s;
    if (entries_.empty()) return s;
    const Entry& e = entries_[k];
    const float r = std::sqrt(u1); // uniform on the triangle: the square-root warp
    s.point = e.a * (1.0f - r) + e.b * (r * (1.0f - u2)) + e.c * (r * u2);
    s.normal = e.normal;
    s.albedoOverPi = e.albedoOverPi;
    s.pdfArea = e.pdfArea;
    s.entry = int(k);
    return s;
}

} // namespace pb::probes
