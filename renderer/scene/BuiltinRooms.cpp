#include "scene/BuiltinScenes.h"
#include "scene/SceneBuilder.h"

namespace pb::scene {

namespace {
constexpr float kHeight = 2.6f;     // interior floor to ceiling
constexpr float kOuter = 0.2f;      // outer walls, floor and ceiling slabs
constexpr float kPartition = 0.05f; // the wall the light-leak tests are about
} // namespace

// The light-leak case: two rooms side by side (x in [-4, 4], z in [-2.5, 2.5]) split at x = 0
// by a 5 cm wall with a doorway. Only the sunlit room (x < 0) has a window; the sun shines
// through it onto that room's floor and never reaches the doorway, so the dark room (x > 0)
// receives light only through the doorway. Everything else is closed: thick boxes overlapping
// at every joint, so probes interpolating across the thin wall are the only way to leak.
Scene makeRoomsScene() {
    Scene s;
    s.name = "rooms";
    SceneBuilder b(s);
    const int wall = b.material("plaster", {0.75f, 0.75f, 0.72f});
    const int floor = b.material("wood_floor", {0.45f, 0.32f, 0.22f});
    const int ceiling = b.material("ceiling", {0.8f, 0.8f, 0.8f});
    const int blue = b.material("blue_fabric", {0.15f, 0.25f, 0.6f});
    const int orange = b.material("orange_paint", {0.8f, 0.4f, 0.1f});

    const float o = kOuter, h = kHeight, x = 4.0f, z = 2.5f;
    b.box("floor", {-x - o, -o, -z - o}, {x + o, 0, z + o}, floor);
    b.box("ceiling", {-x - o, h, -z - o}, {x + o, h + o, z + o}, ceiling);
    b.box("wall_west", {-x - o, -o, -z - o}, {-x, h + o, z + o}, wall);
    b.box("wall_east", {x, -o, -z - o}, {x + o, h + o, z + o}, wall);
    b.box("wall_south", {-x - o, -o, -z - o}, {x + o, h + o, -z}, wall);
    // North wall, with the sunlit room's window: x in [-3.4, -2.2], y in [0.9, 2.1].
    b.box("wall_north_west", {-x - o, -o, z}, {-3.4f, h + o, z + o}, wall);
    b.box("wall_north_sill", {-3.4f, -o, z}, {-2.2f, 0.9f, z + o}, wall);
    b.box("wall_north_lintel", {-3.4f, 2.1f, z}, {-2.2f, h + o, z + o}, wall);
    b.box("wall_north_east", {-2.2f, -o, z}, {x + o, h + o, z + o}, wall);
    // The 5 cm partition, doorway z in [-0.45, 0.45], y in [0, 2.1]. It reaches 1 cm into the
    // floor, ceiling and outer walls so that no crack opens at its joints.
    const float p = kPartition * 0.5f, e = 0.01f;
    b.box("partition_south", {-p, -e, -z - e}, {p, h + e, -0.45f}, wall);
    b.box("partition_north", {-p, -e, 0.45f}, {p, h + e, z + e}, wall);
    b.box("partition_lintel", {-p, 2.1f, -0.45f}, {p, h + e, 0.45f}, wall);

    // Sunlit room: a table and a tall cabinet. Dark room: a sofa and a pillar.
    b.box("table", {-2.2f, 0, -1.6f}, {-1.0f, 0.75f, -0.8f}, orange, 10.0f);
    b.box("cabinet", {-3.95f, 0, -0.6f}, {-3.45f, 1.9f, 0.6f}, wall);
    b.box("sofa", {1.5f, 0, -2.4f}, {3.3f, 0.8f, -1.6f}, blue);
    b.box("pillar", {1.8f, -e, -1.0f}, {2.1f, h + e, -0.7f}, wall);

    // Travelling (0.4, -0.55, -0.75): through the window the beam lands on the sunlit floor
    // at x in [-2.75, -0.67], z in [-0.36, 1.27], short of the partition at x = -0.025.
    s.sun.toSun = glm::normalize(glm::vec3(-0.4f, 0.55f, 0.75f));
    s.sun.intensity = 3.0f;
    s.exposure = 1.5f;
    b.view("sunlit_room", {-0.6f, 1.6f, -2.2f}, {-2.8f, 0.9f, 2.5f}, 70.0f); // window, sun patch
    b.view("dark_room", {3.8f, 1.6f, 2.2f}, {0.5f, 0.6f, -1.0f}, 70.0f);
    // From the dark room through the doorway at the sunlit patch on the other side.
    b.view("doorway", {3.0f, 1.6f, 0.0f}, {-1.7f, 0.0f, 0.5f}, 60.0f);
    return s;
}

// Issue 18: `rooms` with three boxes hanging in the air, marked dynamic (not baked, lit from
// the probes at run time - gi.dynamic): one in the sunlit room's air by the window, one under
// its ceiling, one in the dark room. None touches a surface, so their light comes
// from probes a sparse bake does not keep for any surface: the free-space lattice and its
// stand-ins (renderer/probes/AbsentProbeFill.h). The view `dynamic` sees the two in the sunlit
// room.
Scene makeRoomsDynamicScene() {
    Scene s = makeRoomsScene();
    s.name = "rooms_dynamic";
    SceneBuilder b(s);
    const int red = b.material("red_plastic", {0.7f, 0.15f, 0.12f});
    const int green = b.material("green_plastic", {0.2f, 0.6f, 0.25f});
    const int white = b.material("white_plastic", {0.8f, 0.8f, 0.8f});
    b.box("dynamic_sunlit", {-2.9f, 1.0f, 0.3f}, {-2.5f, 1.4f, 0.7f}, red, 30.0f, true);
    b.box("dynamic_high", {-1.7f, 1.8f, -1.0f}, {-1.3f, 2.2f, -0.6f}, white, 0.0f, true);
    b.box("dynamic_dark", {2.3f, 1.2f, 0.6f}, {2.7f, 1.6f, 1.0f}, green, 45.0f, true);
    // From the sunlit room's south-east corner, at the two sunlit-room boxes.
    b.view("dynamic", {-0.4f, 1.5f, -2.2f}, {-1.6f, 1.3f, 0.6f}, 75.0f);
    return s;
}

} // namespace pb::scene
