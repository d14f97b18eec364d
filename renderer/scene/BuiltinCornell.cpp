#include "scene/BuiltinScenes.h"
#include "scene/SceneBuilder.h"

namespace pb::scene {

// A 2 m Cornell box (the interior spans x,z in [-1, 1], y in [0, 2]), closed on all six sides
// so no light escapes: the bake's convergence tests need an energy-conserving enclosure.
// Walls are 10 cm thick boxes that overlap at the edges, so there are no cracks either.
// The ceiling panel is the only light (sun off, black sky).
Scene makeCornellScene() {
    Scene s;
    s.name = "cornell";
    SceneBuilder b(s);
    // The reflectances of the measured box.
    const int white = b.material("white", {0.725f, 0.71f, 0.68f});
    const int red = b.material("red", {0.63f, 0.065f, 0.05f});
    const int green = b.material("green", {0.14f, 0.45f, 0.091f});
    // Floor irradiance below a 0.6 m panel 2 m up is about 0.09 x its radiance, so 16 puts
    // the floor near 0.35 before bounces: a mid-grey image at exposure 1.
    const int light = b.material("light", {0.78f, 0.78f, 0.78f}, {16.0f, 14.0f, 11.0f});

    const float t = 0.1f, w = 1.0f + t;
    b.box("floor", {-w, -t, -w}, {w, 0, w}, white);
    b.box("ceiling", {-w, 2, -w}, {w, 2 + t, w}, white);
    b.box("back_wall", {-w, -t, -w}, {w, 2 + t, -1}, white);
    b.box("front_wall", {-w, -t, 1}, {w, 2 + t, w}, white);
    b.box("left_wall", {-w, -t, -w}, {-1, 2 + t, w}, red);
    b.box("right_wall", {1, -t, -w}, {w, 2 + t, w}, green);
    // Half sunk into the ceiling: only its underside (and 1 cm of edge) shows.
    b.box("light", {-0.3f, 1.99f, -0.3f}, {0.3f, 2.01f, 0.3f}, light);
    b.box("short_box", {0.05f, 0, 0.05f}, {0.65f, 0.6f, 0.65f}, white, -18.0f);
    b.box("tall_box", {-0.7f, 0, -0.65f}, {-0.1f, 1.2f, -0.05f}, white, 17.0f);

    s.sun.enabled = false;
    s.sky.radiance = glm::vec3(0.0f);
    s.exposure = 1.0f;
    // The classic framing from inside the (closed) front wall: wide enough to see the light.
    b.view("front", {0.0f, 0.95f, 0.95f}, {0.0f, 1.15f, -1.0f}, 80.0f);
    b.view("corner", {0.85f, 1.8f, 0.85f}, {-0.4f, 0.4f, -0.5f}, 70.0f);
    return s;
}

} // namespace pb::scene
