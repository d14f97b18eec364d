#pragma once
// The path tracer's view of a scene in Embree 3: every instance the rasterizer's GBuffer draws
// (static and dynamic; invisible materials left out, as GBufferPass skips them), with the
// GBuffer's per-pixel material: base colour factor x the base colour texture (sRGB decoded,
// bilinear, repeat), emissive factor x the emissive texture, the interpolated vertex normal,
// the alpha test (MASK: its cutoff; BLEND: 0.5, as GBufferPass sets u_alphaCutoff), and
// double-sidedness. Unlike raytrace/RayScene (which keeps the mean texture colour, enough
// for probes), a hit here reads the texel the rasterizer would read.
//
// Camera rays skip the back faces of single-sided triangles, as the rasterizer culls them;
// every other ray treats every triangle as opaque on both sides (as the bake does).
#include "scene/Scene.h"

#include <embree3/rtcore.h>
#include <limits>
#include <vector>

namespace pb::truth {

// What a hit point looks like to the shading code.
struct SurfaceHit {
    float t = -1.0f;         // < 0: miss
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f}; // unit, on the side the ray arrived from
    glm::vec3 shadingNormal{0.0f};   // unit, interpolated, on the same side
    glm::vec3 albedo{0.0f};          // clamped to [0,1] as the sRGB8 GBuffer stores it
    glm::vec3 emitted{0.0f};         // radiance leaving towards the ray (0 from a back face
                                     // of a single-sided emitter)
    unsigned geomID = RTC_INVALID_GEOMETRY_ID, primID = 0;
    bool hit() const { return t >= 0.0f; }
};

// One emissive triangle, in world space (the light sampler's unit).
struct EmissiveTriangle {
    glm::vec3 a, b, c;
    glm::vec2 uvA{0.0f}, uvB{0.0f}, uvC{0.0f};
    glm::vec3 normal;        // unit front face normal
    float area = 0.0f;
    bool twoSided = false;
    int material = 0;
    unsigned geomID = 0, primID = 0;
    glm::vec3 meanEmission{0.0f}; // factor x mean texture colour: the power estimate
};

class TruthScene {
public:
    explicit TruthScene(const scene::Scene& scene);
    ~TruthScene();
    TruthScene(const TruthScene&) = delete;
    TruthScene& operator=(const TruthScene&) = delete;

    // Closest surface along o + t d (d unit) in (tnear, tfar); camera = cull single-sided back
    // faces. Alpha-tested texels are stepped through.
    SurfaceHit intersect(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar,
                         bool camera) const;
    bool occluded(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) const;
    // Emitted radiance of an emissive triangle at barycentrics (u, v), seen from its front.
    glm::vec3 emission(const EmissiveTriangle& tri, float u, float v) const;

    const std::vector<EmissiveTriangle>& emissiveTriangles() const { return emissive_; }
    // Index into emissiveTriangles() of a hit triangle, -1 when it does not emit.
    int emissiveIndex(unsigned geomID, unsigned primID) const;
    bool empty() const { return geoms_.empty(); }
    const scene::Bounds& bounds() const { return bounds_; }
    // Offset for rays leaving a surface, relative to the scene's size (as RayScene's).
    float epsilon() const { return epsilon_; }

private:
    struct Geom {
        std::vector<glm::vec3> positions, normals;
        std::vector<glm::vec2> uvs; // empty: none
        std::vector<std::uint32_t> indices;
        std::vector<glm::vec3> faceNormals;
        std::vector<int> emissiveIndex; // per triangle; empty when the material does not emit
        int material = 0;
        float alphaCutoff = -1.0f;      // < 0: opaque
    };
    glm::vec4 baseColour(const Geom& g, const glm::vec2& uv) const;
    glm::vec2 uvAt(const Geom& g, unsigned prim, float u, float v) const;
    bool passes(const Geom& g, unsigned prim, float u, float v) const; // alpha test
    SurfaceHit shade(const glm::vec3& o, const glm::vec3& d, float t, unsigned geomID,
                     unsigned primID, float u, float v) const;

    const scene::Scene& scene_;
    RTCDevice device_ = nullptr;
    RTCScene rtc_ = nullptr;
    std::vector<Geom> geoms_;                // by Embree geometry id
    std::vector<EmissiveTriangle> emissive_;
    scene::Bounds bounds_;
    bool anyAlphaTest_ = false;
    float epsilon_ = 1e-4f;
};

} // namespace pb::truth
