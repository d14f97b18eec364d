#include "scene/BuiltinScenes.h"
#include "scene/SceneBuilder.h"

namespace pb::scene {

// Two closed 2 x 2 x 2 m rooms side by side (x in [-2, 0] and [0, 2]) sharing one wall 10 cm
// thick at x = 0, thinner than a probe cell: the leak test of the GI techniques (issue 19).
// Only the west room is lit (an emissive ceiling panel); sun off, black sky, so every photon
// on the east side of the wall came through the probes, not through the scene.
Scene makeThinWallScene() {
    Scene s;
    s.name = "thin_wall";
    SceneBuilder b(s);
    const int white = b.material("white", {0.7f, 0.7f, 0.7f});
    const int light = b.material("light", {0.78f, 0.78f, 0.78f}, {16.0f, 14.0f, 11.0f});
    const float t = 0.1f, h = 0.05f; // outer shell thickness, half the shared wall's
    b.box("floor", {-2 - t, -t, -1 - t}, {2 + t, 0, 1 + t}, white);
    b.box("ceiling", {-2 - t, 2, -1 - t}, {2 + t, 2 + t, 1 + t}, white);
    b.box("north_wall", {-2 - t, -t, -1 - t}, {2 + t, 2 + t, -1}, white);
    b.box("south_wall", {-2 - t, -t, 1}, {2 + t, 2 + t, 1 + t}, white);
    b.box("west_wall", {-2 - t, -t, -1 - t}, {-2, 2 + t, 1 + t}, white);
    b.box("east_wall", {2, -t, -1 - t}, {2 + t, 2 + t, 1 + t}, white);
    b.box("shared_wall", {-h, 0, -1}, {h, 2, 1}, white);
    b.box("light", {-1.3f, 1.99f, -0.3f}, {-0.7f, 2.01f, 0.3f}, light);
    s.sun.enabled = false;
    s.sky.radiance = glm::vec3(0.0f);
    s.exposure = 1.0f;
    b.view("lit_room", {-1.9f, 1.2f, 0.9f}, {0.0f, 0.8f, -0.3f}, 75.0f);
    b.view("dark_room", {1.9f, 1.2f, 0.9f}, {0.0f, 0.8f, -0.3f}, 75.0f);
    return s;
}

} // namespace pb::scene
