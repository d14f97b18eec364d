#pragma once
// The bake's view of a scene in Embree 3: the static, visible triangles flattened to world
// space (one triangle mesh per instance), with what shading a hit needs per geometry.
//
// Excluded: dynamic instances (not baked) and invisible materials (BLEND with alpha 0: rays
// pass through). MASK and other BLEND materials are traced as opaque (no alpha test: see
// README.md, open problems).
// Albedo  = baseColor factor x the MEAN linear colour of the base colour texture (sRGB
// decoded); emissive = emissive factor x the mean linear emissive texture colour. Probes
// capture low-frequency light, and the mean keeps hits free of UV interpolation.
#include "raytrace/EmitterTable.h"
#include "scene/Scene.h"

#include <embree3/rtcore.h>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace pb::raytrace {

struct SurfaceInfo {
    glm::vec3 albedo{0.8f};
    glm::vec3 emissive{0.0f};
    bool doubleSided = false;
};

struct MaterialSummary {
    glm::vec3 albedo;
    glm::vec3 emissive;
    bool doubleSided;
    bool invisible;
};

// Per-material values the bake uses (also hashed as bake inputs).
std::vector<MaterialSummary> summariseMaterials(const scene::Scene& scene);

// An Embree ray from o along d over [tnear, tfar], every other field at its neutral value
// (shared by every Embree caller, so no ray starts with a stale field).
void initEmbreeRay(RTCRay& r, const glm::vec3& o, const glm::vec3& d, float tnear, float tfar);

struct RayHit {
    float t = -1.0f; // < 0: miss
    unsigned geomID = RTC_INVALID_GEOMETRY_ID, primID = 0;
    // What Embree returns with the hit, so shading needs no load from the triangle arrays
    // (those loads were cache misses, one or more per hit): the geometric normal as Embree
    // computed it (not unit, not yet on the front side: RayScene::hitNormal) and the
    // barycentrics of corners b (u) and c (v) of triangleCorners.
    glm::vec3 ng{0.0f};
    float u = 0.0f, v = 0.0f;
    bool hit() const { return t >= 0.0f; }
};

// One traced ray, for replaying a bake's exact rays against bare Embree (bench_bake).
struct RecordedRay {
    glm::vec3 origin, dir;
    float tnear, tfar;
    bool shadow; // rtcOccluded1 (else rtcIntersect1)
};

class RayScene {
public:
    explicit RayScene(const scene::Scene& scene);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    RTCScene handle() const { return scene_; }
    // Closest hit along o + t*d, t in [tnear, tfar]; d need not be unit (t scales with it).
    RayHit intersect(const glm::vec3& o, const glm::vec3& d, float tnear = 0.0f,
                     float tfar = std::numeric_limits<float>::infinity()) const {
        RayHit h;
        intersect(o, d, h, tnear, tfar);
        return h;
    }
    // The same into `out`, for loops that keep many hits: a returned RayHit is written field
    // by field and then copied in 16-byte pieces, which stalls on store forwarding (about a
    // tenth of the bake's own shading time).
    void intersect(const glm::vec3& o, const glm::vec3& d, RayHit& out, float tnear = 0.0f,
                   float tfar = std::numeric_limits<float>::infinity()) const;
    // n rays from one origin, t in [0, inf): out[i] as intersect(o, dirs[i], out[i]) gives it,
    // in one call (a probe's rays: a call and a context set-up a ray were 3% of the bake's own
    // CPU).
    void intersect(const glm::vec3& o, const glm::vec3* dirs, std::size_t n, RayHit* out) const;
    bool occluded(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) const;
    // The distance of hit `h` of the ray o + t*d recomputed in double precision against its
    // triangle's plane, rounded to float; Embree's own t when the ray runs along the plane.
    // Embree divides with an approximate reciprocal (rcpps/rcp14 and a Newton step) whose last
    // bits differ between CPU vendors, and one ulp of t moved the gate's cache counters by up
    // to 1900 lines (a floor on a probe plane); this t is the same on every x86-64 CPU. For
    // figures that must hold on another machine (the cost model's and the coverage's primary
    // hits, views/WorstCaseView.cpp); the bake keeps Embree's t.
    float portableDistance(const glm::vec3& o, const glm::vec3& d, const RayHit& h) const;
    const SurfaceInfo& surface(unsigned geomID) const { return surfaces_[geomID]; }
    // Unit face normal of a triangle, on its front side (glTF: counter-clockwise, flipped for
    // instances whose transform mirrors).
    const glm::vec3& faceNormal(unsigned geomID, unsigned primID) const {
        return normals_[geomID][primID];
    }
    // The same front-side unit normal from the hit's own data (RayHit::ng): equal to
    // faceNormal up to the last bits of the rounding, without its memory read. A hit never
    // has a zero ng (Embree rejects degenerate triangles); faceNormal covers it anyway.
    glm::vec3 hitNormal(const RayHit& h) const {
        const float len = glm::length(h.ng);
        if (!(len > 0.0f) || !(len <= std::numeric_limits<float>::max()))
            return faceNormal(h.geomID, h.primID);
        return h.ng * (ngSign_[h.geomID] / len);
    }
    // Geometries (ids 0 .. geometryCount()-1; an id without triangles has none) and their
    // triangles' world-space corners, as traced (LitSurfaces.h samples points on them).
    unsigned geometryCount() const { return unsigned(surfaces_.size()); }
    std::size_t triangleCount(unsigned geomID) const { return normals_[geomID].size(); }
    void triangleCorners(unsigned geomID, unsigned primID, glm::vec3& a, glm::vec3& b,
                         glm::vec3& c) const;
    const scene::Bounds& bounds() const { return bounds_; }
    // The emissive triangles, for sampling them directly (EmitterTable.h).
    const EmitterTable& emitters() const { return emitters_; }
    // Starts loading what shading a hit reads (its face normal: a cache miss per hit).
    void prefetchSurface(const RayHit& h) const {
        if (h.hit()) __builtin_prefetch(&normals_[h.geomID][h.primID]);
    }

    // Benchmark instrumentation: while recording, every intersect/occluded call (from any
    // thread) is logged. Off by default; costs one relaxed atomic load per ray when off.
    void startRecording();
    std::vector<RecordedRay> stopRecording();
    std::size_t triangleCount() const { return triangles_; }
    // Offset for secondary rays leaving a surface: relative to the scene size, since scenes
    // range from centimetres to hundreds of metres.
    float epsilon() const { return epsilon_; }

private:
    struct Recorder;
    void record(const RecordedRay& r) const;
    std::unique_ptr<Recorder> recorder_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<SurfaceInfo> surfaces_;
    std::vector<float> ngSign_; // [geomID]: Embree's ng times this faces the front side
    std::vector<std::vector<glm::vec3>> normals_;
    std::vector<std::vector<glm::vec3>> vertices_;      // [geomID]: world space
    std::vector<std::vector<std::uint32_t>> indices_;   // [geomID]: 3 per triangle
    EmitterTable emitters_;
    scene::Bounds bounds_;
    std::size_t triangles_ = 0;
    float epsilon_ = 1e-4f;
};

// World bounds of what the bake traces (static, visible); empty for an empty scene.
scene::Bounds staticBakeBounds(const scene::Scene& scene);

} // namespace pb::raytrace
