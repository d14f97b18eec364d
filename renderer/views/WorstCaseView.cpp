#include "views/WorstCaseView.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "raytrace/RayScene.h"

#include <algorithm>
#include <cmath>

namespace pb::views {

namespace {

// Sums over some pixels of one view; combined in a fixed order, so results do not depend on
// the thread count.
struct Tally {
    long long covered = 0, overlap = 0, dynamic = 0;
    double distance = 0;
    int maxOverlap = 0;
    void add(const Tally& o) {
        covered += o.covered;
        dynamic += o.dynamic;
        overlap += o.overlap;
        distance += o.distance;
        maxOverlap = std::max(maxOverlap, o.maxOverlap);
    }
};

// The primary rays of a view, with RenderView's conventions (glm::lookAt basis: up is +Y
// unless the camera looks almost straight up or down; row 0 is the top of the image).
struct Camera {
    glm::vec3 eye, f, s, u;
    float tx, ty;
    int width, height;

    Camera(const scene::View& view, int w, int h) : eye(view.position), width(w), height(h) {
        glm::vec3 dir = view.target - view.position;
        const float len = glm::length(dir);
        if (!(len > 0.0f) || !std::isfinite(len))
            throw Error("camera '" + view.name + "': position and target coincide");
        f = dir / len;
        const glm::vec3 up = std::abs(f.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        s = glm::normalize(glm::cross(f, up));
        u = glm::cross(s, f);
        ty = std::tan(glm::radians(view.fovYDegrees) * 0.5f);
        tx = ty * float(w) / float(h);
    }
    glm::vec3 ray(int x, int y) const {
        const float nx = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
        const float ny = 1.0f - (float(y) + 0.5f) / float(height) * 2.0f;
        return glm::normalize(f + nx * tx * s + ny * ty * u);
    }
};

Coverage finish(const Tally& t, int width, int height) {
    Coverage c;
    c.width = width;
    c.height = height;
    c.fraction = double(t.covered) / (double(width) * double(height));
    c.maxOverlap = t.maxOverlap;
    c.dynamicFraction = double(t.dynamic) / (double(width) * double(height));
    if (t.covered > 0) {
        c.meanOverlap = double(t.overlap) / double(t.covered);
        c.meanDistance = t.distance / double(t.covered);
    }
    return c;
}

scene::View poseView(const glm::vec3& eye, float yawDeg, float pitchDeg, float fov) {
    const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
    const glm::vec3 dir(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                        -std::cos(pitch) * std::cos(yaw));
    scene::View v;
    v.name = "worst_case";
    v.position = eye;
    v.target = eye + dir;
    v.fovYDegrees = fov;
    return v;
}

struct Pose {
    glm::vec3 eye{0.0f};
    float yaw = 0, pitch = 0;
    bool nearNamedView = false; // seeded from one of the scene's own views
    Coverage coverage;
    double score = -1;
};

// Heading and pitch (degrees) of a direction, inverse of poseView.
glm::vec2 yawPitch(const glm::vec3& dir) {
    const glm::vec3 d = glm::normalize(dir);
    return {glm::degrees(std::atan2(d.x, -d.z)),
            glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)))};
}

// Scoring heights of the coarse search and of the refinement (widths follow the aspect).
constexpr int kSearchH = 18, kRefineH = 36;
constexpr int kMaxSearchVolumes = 8; // volumes whose interiors seed eye positions
constexpr int kRefined = 4;          // best coarse poses refined
constexpr int kVerified = 16; // coarse poses checked at full resolution when no refined one is full

} // namespace

CoverageTester::CoverageTester(const scene::Scene& scene, const probes::ProbeSet& probes,
                               std::vector<bool> keptVolumes)
    : probes_(probes), kept_(std::move(keptVolumes)), views_(scene.views),
      rays_(std::make_unique<raytrace::RayScene>(scene)) {
    // Dynamic objects are in the GBuffer and lit per pixel like any surface (gi.dynamic): the
    // primary rays see them too, through a scene of them alone (the bake's RayScene leaves
    // them out). Without any, nothing changes.
    scene::Scene dynamicOnly = scene;
    dynamicOnly.instances.clear();
    for (const scene::Instance& inst : scene.instances)
        if (inst.dynamic) {
            dynamicOnly.instances.push_back(inst);
            dynamicOnly.instances.back().dynamic = false;
        }
    if (!dynamicOnly.instances.empty())
        dynamicRays_ = std::make_unique<raytrace::RayScene>(dynamicOnly);
    if (!kept_.empty() && kept_.size() != probes.volumes.size())
        throw Error("coverage: " + std::to_string(kept_.size()) + " kept flags for " +
                    std::to_string(probes.volumes.size()) + " volumes");
    const scene::Bounds b = rays_->bounds();
    sceneSize_ = b.empty() ? 1.0f : std::max(glm::length(b.size()), 1e-6f);
}

CoverageTester::~CoverageTester() = default;

namespace {
// The first hit of a primary ray among the static scene and the dynamic objects.
struct PrimaryHit {
    raytrace::RayHit hit;
    const raytrace::RayScene* scene = nullptr; // whose geomID the hit names
    bool dynamic = false;
};
struct PrimaryRays {
    const raytrace::RayScene& statics;
    const raytrace::RayScene* dynamics; // null: the scene has none
    // Hit distances from RayScene::portableDistance: the same on every CPU (the gate's model
    // counters and the worst-case view search must not depend on Embree's rounding).
    PrimaryHit intersect(const glm::vec3& eye, const glm::vec3& d) const {
        PrimaryHit h{portable(statics, eye, d), &statics, false};
        if (dynamics) {
            const raytrace::RayHit dh = portable(*dynamics, eye, d);
            if (dh.hit() && (!h.hit.hit() || dh.t < h.hit.t)) h = {dh, dynamics, true};
        }
        return h;
    }
    static raytrace::RayHit portable(const raytrace::RayScene& s, const glm::vec3& eye,
                                   const glm::vec3& d) {
        raytrace::RayHit hit = s.intersect(eye, d);
        hit.t = s.portableDistance(eye, d, hit);
        return hit;
    }
};

// overlapRow (optional): volumes containing each pixel's surface point, 0 = needs no GI.
Tally tallyRow(const PrimaryRays& rays, const probes::ProbeSet& set,
               const std::vector<bool>& kept, const Camera& cam, int y, int* overlapRow = nullptr) {
    Tally t;
    for (int x = 0; x < cam.width; ++x) {
        const glm::vec3 d = cam.ray(x, y);
        const PrimaryHit primary = rays.intersect(cam.eye, d);
        const raytrace::RayHit& hit = primary.hit;
        if (overlapRow) overlapRow[x] = 0;
        if (!hit.hit()) continue; // sky: no GI
        const glm::vec3 p = cam.eye + d * hit.t;
        int inside = 0;
        for (size_t v = 0; v < set.volumes.size(); ++v)
            if ((kept.empty() || kept[v]) && set.volumes[v].contains(p)) ++inside;
        if (overlapRow) overlapRow[x] = inside;
        if (inside == 0) continue; // outside every volume: the ambient fallback, no GI
        ++t.covered;
        t.dynamic += primary.dynamic ? 1 : 0;
        t.overlap += inside;
        t.distance += hit.t;
        t.maxOverlap = std::max(t.maxOverlap, inside);
    }
    return t;
}
} // namespace

Coverage CoverageTester::measure(const scene::View& view, int width, int height) const {
    if (width < 1 || height < 1) throw Error("coverage: resolution must be at least 1x1");
    const Camera cam(view, width, height);
    std::vector<Tally> rows(static_cast<size_t>(height));
    pb::parallelFor(size_t(height), 0, [&](size_t y, int) {
        rows[y] = tallyRow(PrimaryRays{*rays_, dynamicRays_.get()}, probes_, kept_, cam, int(y));
    });
    Tally total;
    for (const Tally& r : rows)
        total.add(r);
    return finish(total, width, height);
}

std::vector<int> CoverageTester::overlapImage(const scene::View& view, int width,
                                              int height) const {
    if (width < 1 || height < 1) throw Error("coverage: resolution must be at least 1x1");
    const Camera cam(view, width, height);
    std::vector<int> image(size_t(width) * size_t(height), 0);
    pb::parallelFor(size_t(height), 0, [&](size_t y, int) {
        tallyRow(PrimaryRays{*rays_, dynamicRays_.get()}, probes_, kept_, cam, int(y), &image[y * size_t(width)]);
    });
    return image;
}

std::vector<SurfacePoint>
CoverageTester::surfacePoints(const scene::View& view, int width, int height,
                              const std::vector<glm::ivec2>& pixels) const {
    if (width < 1 || height < 1) throw Error("coverage: resolution must be at least 1x1");
    const Camera cam(view, width, height);
    std::vector<SurfacePoint> out(pixels.size());
    constexpr size_t kChunk = 1024;
    pb::parallelFor((pixels.size() + kChunk - 1) / kChunk, 0, [&](size_t chunk, int) {
        const size_t end = std::min(pixels.size(), (chunk + 1) * kChunk);
        for (size_t i = chunk * kChunk; i < end; ++i) {
            const glm::vec3 d = cam.ray(pixels[i].x, pixels[i].y);
            const PrimaryHit primary = PrimaryRays{*rays_, dynamicRays_.get()}.intersect(cam.eye, d);
            const raytrace::RayHit& hit = primary.hit;
            if (!hit.hit()) continue;
            SurfacePoint& s = out[i];
            s.hit = true;
            s.position = cam.eye + d * hit.t;
            s.normal = primary.scene->faceNormal(hit.geomID, hit.primID);
            // The GBuffer turns double-sided surfaces towards the viewer (gl_FrontFacing).
            if (primary.scene->surface(hit.geomID).doubleSided && glm::dot(s.normal, d) > 0.0f)
                s.normal = -s.normal;
        }
    });
    return out;
}

Coverage CoverageTester::measureSerial(const scene::View& view, int width, int height) const {
    const Camera cam(view, width, height);
    Tally total;
    for (int y = 0; y < height; ++y)
        total.add(tallyRow(PrimaryRays{*rays_, dynamicRays_.get()}, probes_, kept_, cam, y));
    return finish(total, width, height);
}

double CoverageTester::score(const Coverage& c) const {
    // Depth counts until the view sees 10% of the scene's diagonal on average: deeper than
    // that is "a real view"; beyond it, the search prefers poses near the scene's own views.
    // With dynamic objects, a view showing them (up to 5% of the frame: more would favour a
    // camera against one of them) ranks above more overlap: their pixels are the ones only
    // free-space probes light (issue 18).
    const double dynamic = dynamicRays_ ? 1e4 * std::min(c.dynamicFraction / 0.05, 1.0) : 0.0;
    return c.fraction * 1e6 + dynamic + c.meanOverlap * 1e3 +
           10.0 * std::min(c.meanDistance / double(sceneSize_), 0.1);
}

bool CoverageTester::eyeIsClear(const glm::vec3& eye) const {
    // 14 directions: the axes and the cube diagonals. Clear = nothing within a small
    // clearance, and few rays seeing single-sided faces from behind (an eye inside a closed
    // object sees only back faces).
    float clearance = 0.01f * sceneSize_;
    for (size_t v = 0; v < probes_.volumes.size(); ++v)
        if ((kept_.empty() || kept_[v]) && probes_.volumes[v].contains(eye))
            clearance = std::min(clearance, 0.25f * probes_.volumes[v].minCellSize());
    int backFaces = 0;
    for (int i = 0; i < 14; ++i) {
        glm::vec3 d(0.0f);
        if (i < 6)
            d[i / 2] = (i % 2) ? -1.0f : 1.0f;
        else
            d = glm::normalize(glm::vec3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
        // Dynamic objects too: an eye inside one of them sees nothing else.
        const PrimaryHit primary = PrimaryRays{*rays_, dynamicRays_.get()}.intersect(eye, d);
        const raytrace::RayHit& hit = primary.hit;
        if (!hit.hit()) continue;
        if (hit.t < clearance) return false;
        const raytrace::RayScene& rs = *primary.scene;
        const bool singleSided = !rs.surface(hit.geomID).doubleSided;
        if (singleSided && glm::dot(rs.faceNormal(hit.geomID, hit.primID), d) > 0.0f)
            ++backFaces;
    }
    return backFaces <= 3;
}

Coverage measureCoverage(const scene::Scene& scene, const probes::ProbeSet& probes,
                         const scene::View& view, int width, int height) {
    return CoverageTester(scene, probes).measure(view, width, height);
}

WorstCase findWorstCaseView(const scene::Scene& scene, const probes::ProbeSet& probes, int width,
                            int height, float fovYDegrees) {
    return findWorstCaseView(CoverageTester(scene, probes), width, height, fovYDegrees);
}

WorstCase findWorstCaseView(const CoverageTester& tester, int width, int height,
                            float fovYDegrees) {
    if (width < 1 || height < 1) throw Error("worst-case view: resolution must be at least 1x1");
    const probes::ProbeSet& set = tester.probes();
    std::vector<int> order;
    for (size_t i = 0; i < set.volumes.size(); ++i)
        if (tester.kept(int(i))) order.push_back(int(i));
    if (order.empty()) throw Error("worst-case view: no probe volume is kept");

    // 1. Candidate eyes: a 4x3x4 grid inside each volume (largest first), clear of geometry.
    //    Directions: 8 headings x 5 pitches (looking down matters: in open scenes the ground
    //    is what fills a frame with GI pixels).
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return set.volumes[size_t(a)].boxVolume() > set.volumes[size_t(b)].boxVolume();
    });
    if (order.size() > size_t(kMaxSearchVolumes)) order.resize(size_t(kMaxSearchVolumes));
    std::vector<Pose> poses;
    for (int v : order) {
        const probes::ProbeVolume& vol = set.volumes[size_t(v)];
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 4; ++k) {
                    const glm::vec3 frac(-0.75f + 0.5f * float(i), -0.5f + 0.5f * float(j),
                                         -0.75f + 0.5f * float(k));
                    const glm::vec3 eye = vol.toWorld(frac * vol.halfExtents);
                    if (!tester.eyeIsClear(eye)) continue;
                    for (int h = 0; h < 8; ++h)
                        for (float pitch : {-75.0f, -45.0f, -20.0f, 0.0f, 20.0f}) {
                            Pose p;
                            p.eye = eye;
                            p.yaw = 45.0f * float(h);
                            p.pitch = pitch;
                            poses.push_back(p);
                        }
                }
    }
    // Seeds from the scene's own views (a person's eye height and a composed shot): their
    // eye with the heading and pitch nudged, preferred when they reach the same coverage.
    for (const scene::View& v : tester.sceneViews()) {
        bool inside = false;
        for (size_t i = 0; i < set.volumes.size(); ++i)
            inside = inside || (tester.kept(int(i)) && set.volumes[i].contains(v.position));
        if (!inside || !tester.eyeIsClear(v.position)) continue;
        const glm::vec2 yp = yawPitch(v.target - v.position);
        for (float dy : {0.0f, -15.0f, 15.0f, -30.0f, 30.0f})
            for (float dp : {0.0f, -10.0f, -20.0f, -35.0f}) {
                Pose p;
                p.eye = v.position;
                p.yaw = yp.x + dy;
                p.pitch = std::clamp(yp.y + dp, -85.0f, 85.0f);
                p.nearNamedView = true;
                poses.push_back(p);
            }
    }
    if (poses.empty())
        throw Error("worst-case view: no point inside the volumes is clear of geometry");

    const float aspect = float(width) / float(height);
    // Scoring resolutions keep the output's aspect ratio (the frustum is what matters).
    auto scoreAll = [&](std::vector<Pose>& list, int h) {
        const int w = std::max(1, int(std::lround(float(h) * aspect)));
        pb::parallelFor(list.size(), 0, [&](size_t i, int) {
            const scene::View view = poseView(list[i].eye, list[i].yaw, list[i].pitch, fovYDegrees);
            list[i].coverage = tester.measureSerial(view, w, h);
            list[i].score = tester.score(list[i].coverage) + (list[i].nearNamedView ? 0.5 : 0.0);
        });
    };
    scoreAll(poses, kSearchH);
    const int candidates = int(poses.size());
    std::stable_sort(poses.begin(), poses.end(),
                     [](const Pose& a, const Pose& b) { return a.score > b.score; });
    // The runners-up, for step 3 when no refined pose stays full at the requested resolution.
    std::vector<Pose> reserve(poses.begin() + std::min(poses.size(), size_t(kRefined)),
                              poses.begin() + std::min(poses.size(), size_t(kVerified)));
    poses.resize(std::min(poses.size(), size_t(kRefined)));

    // 2. Refine each of the best poses: hill-climb on heading, pitch and position with
    //    shrinking steps, at a finer scoring resolution.
    scoreAll(poses, kRefineH);
    for (Pose& best : poses) {
        float angle = 12.0f;
        float step = 0.1f * set.volumes[size_t(order.front())].minCellSize();
        for (int round = 0; round < 3; ++round, angle *= 0.5f, step *= 0.5f) {
            std::vector<Pose> moves;
            for (int m = 0; m < 10; ++m) {
                Pose p = best;
                if (m < 2)
                    p.yaw += m == 0 ? angle : -angle;
                else if (m < 4)
                    p.pitch = std::clamp(p.pitch + (m == 2 ? angle : -angle), -85.0f, 85.0f);
                else {
                    glm::vec3 d(0.0f);
                    d[(m - 4) / 2] = (m % 2) ? -step : step;
                    p.eye += d;
                    if (!tester.eyeIsClear(p.eye)) continue;
                }
                moves.push_back(p);
            }
            scoreAll(moves, kRefineH);
            for (const Pose& p : moves)
                if (p.score > best.score) best = p;
        }
    }

    // 3. The refined poses at the requested resolution (low-resolution rays can miss a thin
    //    gap of sky between them): the best one wins; if none is fully covered there, the
    //    runners-up of the coarse search are checked too.
    WorstCase out;
    double bestScore = -1;
    for (const Pose& p : poses) {
        const scene::View view = poseView(p.eye, p.yaw, p.pitch, fovYDegrees);
        const Coverage c = tester.measure(view, width, height);
        const double sc = tester.score(c) + (p.nearNamedView ? 0.5 : 0.0);
        if (sc > bestScore) {
            bestScore = sc;
            out.view = view;
            out.coverage = c;
        }
    }
    for (const Pose& p : reserve) {
        if (out.coverage.fraction >= 1.0) break;
        const scene::View view = poseView(p.eye, p.yaw, p.pitch, fovYDegrees);
        const Coverage c = tester.measure(view, width, height);
        const double sc = tester.score(c) + (p.nearNamedView ? 0.5 : 0.0);
        if (sc > bestScore) {
            bestScore = sc;
            out.view = view;
            out.coverage = c;
        }
    }
    out.candidates = candidates;
    return out;
}

} // namespace pb::views
