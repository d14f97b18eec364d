#include "stress/StressScene.h"

#include "scene/SceneBuilder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace pb::stress {

namespace {

// Moves every instance, probe and camera by world = offset + scale * position, composed in
// double so the only rounding is the final one to float (exact for the 1/16 m grid).
glm::vec3 place(const StressSceneParams& p, const glm::vec3& local) {
    return glm::vec3(p.offset + p.scale * glm::dvec3(local));
}

void placeInstances(scene::Scene& s, const StressSceneParams& p) {
    for (scene::Instance& inst : s.instances) {
        glm::mat4 t = inst.transform;
        const glm::vec3 origin = place(p, glm::vec3(t[3]));
        glm::mat4 linear = glm::mat4(glm::mat3(t) * float(p.scale));
        linear[3] = glm::vec4(origin, 1.0f);
        inst.transform = linear;
    }
}

void breakNormals(scene::Scene& s) {
    scene::Primitive& prop = s.primitives.back();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < prop.normals.size(); ++i)
        prop.normals[i] = i % 2 ? glm::vec3(0.0f) : glm::vec3(nan, 0.0f, nan);
}

} // namespace

StressScene makeStressScene(const StressSceneParams& p) {
    StressScene out;
    scene::Scene& s = out.scene;
    s.name = "stress_room";
    scene::SceneBuilder b(s);
    const float k = float(p.lightScale);
    const int wall = b.material("wall", {0.7f, 0.7f, 0.68f});
    const int floor = b.material("floor", {0.5f, 0.36f, 0.25f});
    const int block = b.material("block", {0.8f, 0.4f, 0.1f});
    const int panel = b.material("panel", {0.8f, 0.8f, 0.8f}, glm::vec3(2.0f, 1.9f, 1.7f) * k);

    // Interior x, z in [-2, 2], y in [0, 2.5]; 25 cm shells overlapping at the joints.
    const float t = 0.25f;
    b.box("floor", {-2 - t, -t, -2 - t}, {2 + t, 0, 2 + t}, floor);
    b.box("ceiling", {-2 - t, 2.5f, -2 - t}, {2 + t, 2.5f + t, 2 + t}, wall);
    b.box("wall_west", {-2 - t, -t, -2 - t}, {-2, 2.5f + t, 2 + t}, wall);
    b.box("wall_east", {2, -t, -2 - t}, {2 + t, 2.5f + t, 2 + t}, wall);
    b.box("wall_south", {-2 - t, -t, -2 - t}, {2 + t, 2.5f + t, -2}, wall);
    // North wall with the window x in [-0.75, 0.75], y in [1, 2].
    b.box("wall_north_w", {-2 - t, -t, 2}, {-0.75f, 2.5f + t, 2 + t}, wall);
    b.box("wall_north_e", {0.75f, -t, 2}, {2 + t, 2.5f + t, 2 + t}, wall);
    b.box("wall_north_sill", {-0.75f, -t, 2}, {0.75f, 1, 2 + t}, wall);
    b.box("wall_north_lintel", {-0.75f, 2, 2}, {0.75f, 2.5f + t, 2 + t}, wall);
    b.box("block", {-1.25f, 0, -1.25f}, {-0.25f, 1, -0.25f}, block);
    b.box("panel", {-0.5f, 2.4375f, -0.5f}, {0.5f, 2.5625f, 0.5f}, panel);
    if (p.partition > 0.0) {
        const float h = float(p.partition) * 0.5f;
        b.box("partition", {0.5f - h, 0, -2}, {0.5f + h, 2.5f, 2}, wall);
    }
    if (p.hotSpot > 0.0) {
        const int hot = b.material("hot_spot", {0.8f, 0.8f, 0.8f}, glm::vec3(float(p.hotSpot)));
        b.box("hot_spot", {1.25f, 0, 0.75f}, {1.5f, 0.25f, 1}, hot);
    }
    if (p.badNormals) {
        b.box("bad_mesh", {1, 0, -1.5f}, {1.5f, 0.5f, -1}, block);
        breakNormals(s);
    }
    placeInstances(s, p);

    s.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.6f, 0.75f)); // through the window
    s.sun.intensity = 3.0f * k;
    s.sky.radiance = glm::vec3(0.35f, 0.45f, 0.6f) * k;
    s.exposure = p.exposureFollowsLight ? 1.0f / k : 1.0f;
    out.exposure = s.exposure;

    out.view.name = "corner";
    out.view.position = place(p, {-1.75f, 1.75f, 1.75f});
    out.view.target = place(p, {1.25f, 0.25f, -1.25f});
    out.view.fovYDegrees = 75.0f;
    s.views.push_back(out.view);

    probes::ProbeVolume& v = out.volume;
    v.name = "room";
    v.center = place(p, {0.0f, 1.25f, 0.0f});
    v.halfExtents = glm::vec3(glm::dvec3(1.875, 1.125, 1.875) * p.scale);
    v.counts = p.probeCounts;
    return out;
}

} // namespace pb::stress
