#pragma once
// The benchmark's worst-case view (the talk measures every optimization "against a worst-case
// view where the whole GBuffer needs GI"): a camera where every pixel sees geometry inside a
// probe volume, so no pixel takes the sky or outside-every-volume early-out.
//
// GL-free: primary rays through the pixel centres with Embree (the bake's RayScene), using
// the renderer's camera conventions (RenderView: up = +Y, or +Z when looking straight up or
// down; row 0 at the top). A pixel "needs GI" when its ray hits static geometry at a point
// inside the box of at least one kept volume. Dynamic instances are traced too, as the GBuffer
// holds them (issue 18): their pixels need GI like any other, and where a scene has them the
// search prefers a view that shows them (up to 5% of the frame) - the pixels only
// free-space probes light.
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <memory>
#include <vector>

namespace pb::raytrace {
class RayScene;
}

namespace pb::views {

struct Coverage {
    int width = 0, height = 0;
    double fraction = 0;     // pixels needing GI / all pixels (target 1.0)
    int maxOverlap = 0;      // most volumes containing one pixel's surface point
    double meanOverlap = 0;  // volumes per covered pixel, on average
    double meanDistance = 0; // mean hit distance of covered pixels (world units)
    double dynamicFraction = 0; // covered pixels on dynamic objects / all pixels
};

// What the GBuffer holds at one pixel, from the CPU primary ray (for the cost model).
struct SurfacePoint {
    bool hit = false;         // false: sky
    glm::vec3 position{0.0f}; // world hit point
    glm::vec3 normal{0.0f};   // geometric (face) normal, towards the eye on double-sided faces
};

// Casts the coverage rays of one scene + probe set. Building it builds the BVH once (0.2 s
// for 0.2 M triangles), so a search asks it many times.
class CoverageTester {
public:
    // keptVolumes[i] false: volume i is left out (gi.volume_lod); empty: all kept.
    CoverageTester(const scene::Scene& scene, const probes::ProbeSet& probes,
                   std::vector<bool> keptVolumes = {});
    ~CoverageTester();
    Coverage measure(const scene::View& view, int width, int height) const;       // all cores
    Coverage measureSerial(const scene::View& view, int width, int height) const; // 1 thread
    // Per pixel (rows top to bottom): how many kept volumes contain its surface point; 0 =
    // the pixel needs no GI (sky, or outside every volume).
    std::vector<int> overlapImage(const scene::View& view, int width, int height) const;
    // The surface seen through each pixel centre (x, y), row 0 at the top, of a width x height
    // image (all cores; the result does not depend on the thread count).
    std::vector<SurfacePoint> surfacePoints(const scene::View& view, int width, int height,
                                            const std::vector<glm::ivec2>& pixels) const;
    // Ranking of views for the search: full coverage, then overlap, then depth.
    double score(const Coverage& c) const;
    bool kept(int volume) const { return kept_.empty() || kept_[size_t(volume)]; }
    // True when the eye is clear of geometry (not inside a wall or against a surface).
    bool eyeIsClear(const glm::vec3& eye) const;
    const probes::ProbeSet& probes() const { return probes_; }
    const std::vector<scene::View>& sceneViews() const { return views_; }
    bool hasDynamicObjects() const { return dynamicRays_ != nullptr; }

private:
    const probes::ProbeSet& probes_;
    std::vector<bool> kept_;
    std::vector<scene::View> views_;
    std::unique_ptr<raytrace::RayScene> rays_;
    std::unique_ptr<raytrace::RayScene> dynamicRays_; // the dynamic objects alone; null: none
    float sceneSize_ = 1.0f;
};

Coverage measureCoverage(const scene::Scene& scene, const probes::ProbeSet& probes,
                         const scene::View& view, int width, int height);

struct WorstCase {
    scene::View view;
    Coverage coverage;  // at the requested resolution
    int candidates = 0; // poses scored during the search
};

// Searches eyes inside the kept volumes looking in 40 directions, and the scene's own views
// with their heading and pitch nudged, at low resolution; hill-climbs the best 4
// poses and measures those at the requested resolution (then runners-up if none is full). Prefers
// full coverage, then more overlapping volumes, then a view deep enough not to be a camera against
// a wall, then a pose near one of the scene's views. Deterministic. The view keeps
// `fovYDegrees` (default 60).
WorstCase findWorstCaseView(const scene::Scene& scene, const probes::ProbeSet& probes, int width,
                            int height, float fovYDegrees = 60.0f);
WorstCase findWorstCaseView(const CoverageTester& tester, int width, int height,
                            float fovYDegrees = 60.0f);

} // namespace pb::views
