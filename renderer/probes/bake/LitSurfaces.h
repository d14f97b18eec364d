#pragma once
// Directly lit surfaces as secondary lights the bake can sample (next-event estimation toward
// what the sun and the punctual lights light up), picked in proportion to an estimate of their
// reflected power with an alias table.
//
// Why: a probe in a room lit only through a doorway sees its light as a small bright patch -
// the sunlit floor beyond the door - that a few hundred rays find as rarely as they find a
// small emissive panel (EmitterTable.h). The built-in rooms scene baked with tens of percent
// of seed noise in its dark room for that reason. Sampling points on the lit surfaces
// themselves, weighted against the probe's rays by multiple importance sampling
// (RadiancePass.h), removes most of it.
//
// What is sampled is only the directly lit part of a surface's radiance,
//     L_d(x) = albedo / pi * E_direct(x, n_side)        (DirectLight.h)
// evaluated exactly at the sampled point with its shadow rays, so the sampled function is the
// one the rays see at their hits; the rest (emission, E_indirect) stays with the rays.
//
// Patches: each traced triangle is cut into n x n equal sub-triangles (n up to kMaxSplit, so
// no edge is much longer than the scene's extent / kPatchesPerExtent), and each side a patch
// reflects from (the front; the back too when double-sided) is one entry, whose power is
//     area x luminance(albedo / pi x E_direct at the patch centre, that side).
// The estimate only steers the sampling: a patch whose centre is in shadow gets no samples
// but is still found by the rays, whose MIS weight there is 1, so the result stays unbiased.
// Deterministic: the same scene and scenario give the same table, independent of the seed.
#include "core/FloorToInt.h"
#include "core/HugePages.h"
#include "probes/Scenario.h"
#include "raytrace/AliasTable.h"
#include "raytrace/RayScene.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace pb::probes {

struct LitPatchSample {
    glm::vec3 point;
    glm::vec3 normal;         // of the side that reflects toward the sampler (unit)
    glm::vec3 albedoOverPi;
    float pdfArea = 0.0f;     // P(entry) / area(patch)
    int entry = -1;           // LitSurfaces::side(entry) names its triangle and side
};

// Where an entry lies: the RayScene triangle and the side it reflects from.
struct LitPatchSide {
    unsigned geomID = 0, primID = 0;
    bool back = false; // the triangle's back face
};

class LitSurfaces {
public:
    static constexpr int kMaxSplit = 16;
    static constexpr float kPatchesPerExtent = 64.0f;

    LitSurfaces() = default;
    // Builds the table for one scenario's sun and the scene's punctual lights (shadow rays
    // counted into shadowRays); threads as parallelFor's.
    LitSurfaces(const raytrace::RayScene& rs, const Scenario& sc, const std::vector<scene::Light>& lights,
                int threads, std::uint64_t& shadowRays);

    bool empty() const { return entries_.empty(); }
    std::size_t size() const { return entries_.size(); }
    std::size_t patchCount() const { return patches_; }

    // The area density P(entry) / area of the patch holding hit point x of triangle
    // (geomID, primID) on side `back` (false: the front); 0 where nothing is sampled.
    float pdfArea(unsigned geomID, unsigned primID, bool back, const glm::vec3& x) const {
        return pdfAtSlot(slotOf(geomID, primID, back, x));
    }
    // pdfArea in two steps, so that a loop over many hits can prefetch each density before it
    // reads it (the densities are one large array read at random: most of pdfArea's time was
    // that cache miss). slotOf: the hit's patch side, -1 where nothing is sampled.
    std::int64_t slotOf(unsigned geomID, unsigned primID, bool back, const glm::vec3& x) const;
    // slotOf from the hit's barycentrics (RayHit::u, v: corners b and c) instead of its
    // position: the same patch, without reading the triangle's corners.
    // Inline: the bake calls it for every shaded hit (as a call, with subTriangle, 2% of a
    // bake's CPU).
    std::int64_t slotOfBarycentric(unsigned geomID, unsigned primID, bool back, float u,
                                   float v) const {
        const TriangleSlots* t = litSlotsOf(geomID, primID);
        if (!t) return -1;
        u = std::clamp(u, 0.0f, 1.0f);
        v = std::clamp(v, 0.0f, 1.0f);
        return std::int64_t(t->first) + subTriangle(u, v, t->split) * 2 + int(back);
    }
    float pdfAtSlot(std::int64_t slot) const {
        return slot < 0 ? 0.0f : slotPdf_[std::size_t(slot)];
    }
    void prefetchSlot(std::int64_t slot) const {
        if (slot >= 0) __builtin_prefetch(&slotPdf_[std::size_t(slot)]);
    }
    // Hints that slotOf will be asked about this triangle soon (nothing to read for an unlit
    // one: the bitmap that says so is small enough to stay in the cache).
    void prefetchTriangle(unsigned geomID, unsigned primID) const {
        if (const TriangleSlots* t = litSlotsOf(geomID, primID)) __builtin_prefetch(t);
    }

    // u0 picks the entry (alias table), u1, u2 the point (uniform on its patch).
    LitPatchSample sample(float u0, float u1, float u2) const {
        return empty() ? LitPatchSample{} : sampleEntry(pickEntry(u0), u1, u2);
    }
    // sample in steps, for the same reason as slotOf: pick, prefetch, then read the entry.
    // pickEntry must not be called on an empty table.
    std::size_t pickEntry(float u0) const { return pick_.pick(u0); }
    void prefetchPick(float u0) const { pick_.prefetch(u0); }
    void prefetchEntry(std::size_t k) const {
        const char* p = reinterpret_cast<const char*>(&entries_[k]);
        __builtin_prefetch(p);
        __builtin_prefetch(p + sizeof(Entry) - 1); // the same line when the array is aligned
    }
    LitPatchSample sampleEntry(std::size_t k, float u1, float u2) const;
    // Entry k's triangle and side (k < size()): what LitPatchSample leaves out, for checks
    // and diagnostics; the bake never reads it.
    LitPatchSide side(std::size_t k) const { return sides_[k]; }

private:
    // What a sample reads, one cache line (16 floats): the patch's corners, the normal of
    // its reflecting side, albedo / pi and the density. Where it lies is kept apart (sides_):
    // the bake never reads it.
    struct Entry {
        glm::vec3 a, b, c;
        glm::vec3 normal;
        glm::vec3 albedoOverPi;
        float pdfArea;
    };
    static_assert(sizeof(Entry) == 64, "one cache line per sampled entry");
    struct TriangleSlots {
        // Into slotPdf_: n * n * 2 (sub-triangle) * 2 (side); -1 where no patch side is lit
        // (or the triangle reflects nothing).
        std::int32_t first = -1;
        std::int32_t split = 0;  // n
    };
    // Sub-triangle slot of barycentrics (u, v) in an n-split triangle.
    static int subTriangle(float u, float v, int n) {
        const float su = u * float(n), sv = v * float(n);
        // floorToInt, not std::floor (a libm call without SSE4.1): two per shaded hit.
        int i = std::clamp(floorToInt(su), 0, n - 1);
        int j = std::clamp(floorToInt(sv), 0, n - 1);
        if (i + j > n - 1) j = n - 1 - i; // rounding put the point past the far edge
        const bool upper = (su - float(i)) + (sv - float(j)) > 1.0f && i + j <= n - 2;
        return (i * n + j) * 2 + int(upper);
    }
    // The triangle's slots, or nullptr for an id the scene does not have.
    const TriangleSlots* slotsOf(unsigned geomID, unsigned primID) const {
        if (std::size_t(geomID) + 1 >= geometryFirst_.size()) return nullptr;
        const std::size_t k = geometryFirst_[geomID] + primID;
        return k < geometryFirst_[geomID + 1] ? &triangles_[k] : nullptr;
    }
    // The same for a triangle with a lit patch side; nullptr for any other, decided by the
    // bitmap (a bit per triangle: 23 KiB on the decimated Sponza) without reading triangles_,
    // which a hit would read at random (1.5 MiB there).
    const TriangleSlots* litSlotsOf(unsigned geomID, unsigned primID) const {
        // (No bitmap: an empty table, nothing lit.)
        if (litTriangles_.empty() || std::size_t(geomID) + 1 >= geometryFirst_.size())
            return nullptr;
        const std::size_t k = geometryFirst_[geomID] + primID;
        if (k >= geometryFirst_[geomID + 1] || !((litTriangles_[k >> 6] >> (k & 63)) & 1u))
            return nullptr;
        return &triangles_[k];
    }

    // The arrays read at random per hit and per sample: several MiB each on a large scene, so
    // on huge pages (HugePages.h), as the sampler's probe tiles.
    const raytrace::RayScene* rs_ = nullptr;
    HugePageVector<Entry> entries_;
    std::vector<LitPatchSide> sides_;        // per entry
    HugePageVector<TriangleSlots> triangles_; // all geometries' triangles, in id order
    std::vector<std::uint64_t> litTriangles_; // bit per triangle of triangles_: first >= 0
    std::vector<std::size_t> geometryFirst_;  // [geomID]: its first triangle; one past the end
    HugePageVector<float> slotPdf_;           // the entry's pdfArea, or 0
    raytrace::AliasTable pick_; // entries by power
    std::size_t patches_ = 0;
};

} // namespace pb::probes
