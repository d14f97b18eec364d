#include "scene/DefaultView.h"

#include "core/Luminance.h"
#include "scene/RayGrid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pb::scene {

namespace {

// Eye height as a fraction of the bounds' height: near the floor of an interior (where a
// person stands in a one-storey building), low over an exterior's ground.
constexpr float kEyeHeight = 0.3f;
// How far from the centre towards one end of the long axis (0.5 = at the end). 0.35 keeps the
// eye 15% of the length inside the bounds: clear of the end wall of an interior, still
// looking down almost the whole length of the scene.
constexpr float kEyeOffset = 0.35f;
// Looking slightly down (about 8 degrees) shows the floor, where probe GI is most visible.
constexpr float kDownSlope = 0.14f;

// One candidate pose: looking along -sign * axis (axis 0 = X, 2 = Z) from a point placed by
// fractions of the bounds.
struct Pose {
    int axis;
    float sign, along, lateral, height;
};

View poseView(const Bounds& b, const Pose& p) {
    const glm::vec3 size = b.size();
    const int side = 2 - p.axis;
    float length = size[p.axis];
    if (!(length > 0.0f)) length = glm::max(glm::max(size.x, size.z), glm::max(size.y, 1e-3f));
    glm::vec3 eye = b.center();
    eye[p.axis] += p.sign * p.along * length;
    eye[side] += p.lateral * size[side];
    eye.y = b.min.y + p.height * size.y;
    glm::vec3 forward(0.0f);
    forward[p.axis] = -p.sign;
    const float distance = 2.0f * kEyeOffset * length; // to the mirror point at the other end
    View v;
    v.name = "default";
    v.position = eye;
    v.target = eye + forward * distance - glm::vec3(0, kDownSlope * distance, 0);
    return v;
}

bool sceneHasLight(const Scene& s, const RayGrid& grid) {
    return (s.sun.enabled && s.sun.intensity > 0.0f) || luminance(s.sky.radiance) > 0.0f ||
           !s.lights.empty() || !grid.emitterCentroids().empty();
}

// Whether the surface at p (normal n, facing the viewer) receives light directly: shadow rays
// to the sun, towards the sky (normal, halfway up, zenith), to each punctual light and to up to
// 32 emissive triangles' centroids. Unshadowed spot cones are not checked: "some light reaches it".
bool receivesLight(const Scene& s, const RayGrid& grid, glm::vec3 p, glm::vec3 n, float diagonal) {
    const float far = 2.0f * diagonal;
    p += n * (1e-4f * diagonal);
    auto open = [&](glm::vec3 d, float dist) {
        return glm::dot(n, d) > 0.0f && !std::isfinite(grid.cast(p, d, dist).distance);
    };
    if (s.sun.enabled && s.sun.intensity > 0.0f && open(glm::normalize(s.sun.toSun), far))
        return true;
    // The sky: along the normal, halfway to the zenith, or at the zenith (a wall sees the sky
    // above it, not straight ahead).
    if (luminance(s.sky.radiance) > 0.0f) {
        const glm::vec3 up(0.0f, 1.0f, 0.0f);
        if (open(n, far) || open(up, far)) return true;
        const glm::vec3 half = n + up;
        if (glm::dot(half, half) > 1e-6f && open(glm::normalize(half), far)) return true;
    }
    for (const Light& l : s.lights) {
        if (!(l.intensity > 0.0f)) continue;
        if (l.type == LightType::Directional) {
            if (open(-glm::normalize(l.direction), far)) return true;
            continue;
        }
        const glm::vec3 to = l.position - p;
        const float d = glm::length(to);
        if (d > 0.0f && (l.range <= 0.0f || d < l.range) && open(to / d, d * 0.999f))
            return true;
    }
    const std::vector<glm::vec3>& emitters = grid.emitterCentroids();
    const std::size_t stride = std::max<std::size_t>(1, emitters.size() / 32);
    for (std::size_t i = 0; i < emitters.size(); i += stride) {
        const glm::vec3 to = emitters[i] - p;
        const float d = glm::length(to);
        if (d > 0.0f && open(to / d, d * 0.999f)) return true;
    }
    return false;
}

// What a pose sees (DefaultView.h): a 16x9 grid across the 16:9 frustum and 14 rays all
// around the eye (the 6 axes and 8 diagonals). `length` is the scene's long side.
ViewCheck look(const Scene& scene, const RayGrid& grid, const View& v, float length,
               float diagonal) {
    const glm::vec3 f = glm::normalize(v.target - v.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
    const glm::vec3 u = glm::cross(r, f);
    const float th = std::tan(glm::radians(v.fovYDegrees) * 0.5f), tw = th * 16.0f / 9.0f;
    constexpr int kW = 16, kH = 9;
    int front = 0, back = 0, sky = 0, nearHits = 0, lit = 0;
    std::vector<float> depths;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float sx = (2.0f * (float(x) + 0.5f) / kW - 1.0f) * tw;
            const float sy = (2.0f * (float(y) + 0.5f) / kH - 1.0f) * th;
            const glm::vec3 d = glm::normalize(f + sx * r + sy * u);
            const RayHit hit = grid.cast(v.position, d, 2.0f * diagonal);
            if (!std::isfinite(hit.distance)) {
                ++sky;
                continue;
            }
            (hit.backFacing ? back : front) += 1;
            if (!hit.backFacing &&
                (hit.emissive ||
                 receivesLight(scene, grid, v.position + d * hit.distance, hit.normal, diagonal)))
                ++lit;
            nearHits += hit.distance < 0.05f * length;
            depths.push_back(hit.distance / length);
        }
    ViewCheck c;
    const float rays = float(kW * kH);
    c.frontFraction = float(front) / rays;
    c.backFraction = float(back) / rays;
    c.skyFraction = float(sky) / rays;
    c.nearFraction = float(nearHits) / rays;
    c.litFraction = float(lit) / rays;
    c.sceneHasLight = sceneHasLight(scene, grid);
    if (!depths.empty()) {
        std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2),
                         depths.end());
        c.medianDepth = depths[depths.size() / 2];
    }
    c.centreDepth = glm::min(grid.cast(v.position, f, 2.0f * diagonal).distance / length, 2.0f);
    int aroundBack = 0;
    c.eyeClear = true;
    for (int i = 0; i < 14; ++i) {
        glm::vec3 d(0.0f);
        if (i < 6)
            d[i / 2] = i % 2 ? -1.0f : 1.0f;
        else
            d = glm::normalize(glm::vec3(i & 1 ? -1 : 1, i & 2 ? -1 : 1, i & 4 ? -1 : 1));
        const RayHit hit = grid.cast(v.position, d, 2.0f * diagonal);
        aroundBack += std::isfinite(hit.distance) && hit.backFacing;
        if (i < 6) c.eyeClear = c.eyeClear && hit.distance > 0.02f * length;
    }
    // A solid object's single-sided faces all point away from an eye inside it.
    c.insideClosedMesh = aroundBack >= 10;
    return c;
}

// Higher is better, for when no pose is good(): front faces and depth count, back faces,
// sky, an eye in something and geometry right in front count against.
float score(const ViewCheck& c) {
    return 2.0f * c.frontFraction + c.litFraction + glm::min(c.medianDepth, 1.0f) +
           0.5f * glm::min(c.centreDepth, 1.0f) - 3.0f * c.backFraction -
           c.skyFraction - 2.0f * c.nearFraction - (c.eyeClear ? 0.0f : 5.0f) -
           (c.insideClosedMesh ? 10.0f : 0.0f);
}

// Poses outside the bounds looking at their centre: from 8 sides (the axes, then the
// diagonals), elevated 30 then 15 degrees, at 1.1 then 1.5 times the bounding sphere's radius
// (near enough that the model fills most of a 16:9 frame).
std::vector<View> outsideViews(const Bounds& b) {
    std::vector<View> out;
    const glm::vec3 centre = b.center();
    const float radius = 0.5f * glm::length(b.size());
    for (float distance : {1.1f, 1.5f})
        for (float elevation : {30.0f, 15.0f})
            for (int side = 0; side < 8; ++side) {
                const float yaw = glm::radians(45.0f * float(side % 4 * 2 + side / 4));
                const float e = glm::radians(elevation);
                const glm::vec3 dir(std::cos(e) * std::cos(yaw), std::sin(e), std::cos(e) * std::sin(yaw));
                View v;
                v.name = "default";
                v.position = centre + dir * (distance * radius);
                v.target = centre;
                out.push_back(v);
            }
    return out;
}

float longSide(const Bounds& b) {
    const glm::vec3 size = b.size();
    return glm::max(glm::max(size.x, size.z), 1e-3f * glm::length(size));
}

} // namespace

View makeDefaultView(const Bounds& b) {
    if (b.empty()) { // nothing to look at (e.g. "empty"): the glTF camera's default pose
        View v;
        v.name = "default";
        v.position = glm::vec3(0.0f);
        v.target = glm::vec3(0, 0, -1);
        return v;
    }
    const glm::vec3 size = b.size();
    return poseView(b, {size.x > size.z ? 0 : 2, 1.0f, kEyeOffset, 0.0f, kEyeHeight});
}

// The bounds rule first; when its eye is in or against geometry, or something blocks the
// view, nearby poses in a fixed order: other heights, sideways, nearer the centre, then the
// opposite direction and the other horizontal axis. The first pose that sees well wins, else
// the best-scoring one. Each pose is judged by what it sees (look(): front faces, sky, back
// faces, depth, an eye inside a closed mesh, how much of it receives light). Deterministic.
View makeDefaultView(const Scene& scene) { return makeDefaultView(scene, RayGrid(scene)); }

View makeDefaultView(const Scene& scene, const RayGrid& grid) {
    const Bounds b = scene.staticWorldBounds();
    const View simple = makeDefaultView(b);
    if (b.empty() || grid.empty()) return simple;
    const glm::vec3 size = b.size();
    const float diagonal = glm::length(size);
    const int longAxis = size.x > size.z ? 0 : 2;
    const float length = longSide(b);
    View best = simple;
    float bestScore = -1e30f;
    for (int axis : {longAxis, 2 - longAxis})
        for (float sign : {1.0f, -1.0f})
            for (float along : {kEyeOffset, 0.25f, 0.15f, 0.0f})
                for (float lateral : {0.0f, 0.15f, -0.15f, 0.3f, -0.3f})
                    for (float height : {kEyeHeight, 0.45f, 0.2f}) {
                        const View v = poseView(b, {axis, sign, along, lateral, height});
                        const ViewCheck c = look(scene, grid, v, length, diagonal);
                        if (c.good()) return v;
                        if (score(c) > bestScore) {
                            bestScore = score(c);
                            best = v;
                        }
                    }
    // No pose inside the bounds sees well: a model rather than a place (a diorama on a thick
    // base, a statue, a vehicle). Look at it from outside, as one walks around a table.
    for (const View& v : outsideViews(b)) {
        const ViewCheck c = look(scene, grid, v, length, diagonal);
        if (c.good()) return v;
        if (score(c) > bestScore) {
            bestScore = score(c);
            best = v;
        }
    }
    return best;
}

ViewCheck checkView(const Scene& scene, const View& view) {
    const Bounds b = scene.staticWorldBounds();
    const RayGrid grid(scene);
    if (b.empty() || grid.empty()) return {};
    return look(scene, grid, view, longSide(b), glm::length(b.size()));
}

std::string uniqueViewName(const Scene& scene, const std::string& base) {
    const std::string stem = base.empty() ? std::string("view") : base;
    std::string name = stem;
    for (int i = 2; scene.findView(name); ++i)
        name = stem + "_" + std::to_string(i);
    return name;
}

} // namespace pb::scene
