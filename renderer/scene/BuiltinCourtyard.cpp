#include "scene/BuiltinScenes.h"
#include "scene/SceneBuilder.h"

namespace pb::scene {

// Outdoors: a 40 m ground slab, buildings (solid boxes) around an open courtyard, and one
// hollow hall on its west side whose door faces the courtyard: sun and sky reach its
// interior only through that door. Sun and sky are the only lights.
Scene makeCourtyardScene() {
    Scene s;
    s.name = "courtyard";
    SceneBuilder b(s);
    const int ground = b.material("paving", {0.4f, 0.38f, 0.35f});
    const int stone = b.material("sandstone", {0.7f, 0.6f, 0.45f});
    const int brick = b.material("brick", {0.55f, 0.25f, 0.18f});
    const int plaster = b.material("plaster", {0.8f, 0.8f, 0.76f});
    const int green = b.material("hedge", {0.15f, 0.35f, 0.1f});

    b.box("ground", {-20, -0.2f, -20}, {20, 0, 20}, ground);
    // Solid buildings, sunk 10 cm into the ground so no crack shows at their base.
    b.box("north_building", {-9, -0.1f, -12}, {9, 8, -7}, stone);
    b.box("east_building", {7, -0.1f, -7}, {12, 6, 6}, brick);
    b.box("south_building", {6, -0.1f, 9}, {12, 3, 13}, stone);
    // The hall: outer x in [-12, -7], z in [-6, 5], 30 cm walls, 5 m high; door in the east
    // wall at z in [-0.6, 0.6], 2.4 m high.
    const float wt = 0.3f;
    b.box("hall_wall_west", {-12, -0.1f, -6}, {-12 + wt, 5, 5}, plaster);
    b.box("hall_wall_north", {-12, -0.1f, -6}, {-7, 5, -6 + wt}, plaster);
    b.box("hall_wall_south", {-12, -0.1f, 5 - wt}, {-7, 5, 5}, plaster);
    b.box("hall_wall_east_north", {-7 - wt, -0.1f, -6}, {-7, 5, -0.6f}, plaster);
    b.box("hall_wall_east_south", {-7 - wt, -0.1f, 0.6f}, {-7, 5, 5}, plaster);
    b.box("hall_lintel", {-7 - wt, 2.4f, -0.6f}, {-7, 5, 0.6f}, plaster);
    b.box("hall_roof", {-12, 5, -6}, {-7, 5.3f, 5}, brick);
    b.box("hall_column", {-10.4f, -0.1f, 1.5f}, {-10.0f, 5, 1.9f}, stone);
    // Courtyard furniture.
    b.box("fountain", {-1.2f, -0.1f, -1.2f}, {1.2f, 0.6f, 1.2f}, stone);
    b.box("obelisk", {-0.25f, 0.6f, -0.25f}, {0.25f, 4.0f, 0.25f}, stone, 45.0f);
    b.box("hedge", {2.5f, -0.1f, 3.0f}, {6.0f, 1.2f, 4.0f}, green);

    // Morning sun from the east (+X): long shadows across the courtyard, and a patch of sun
    // about 2 m deep on the hall's floor through its east-facing door.
    s.sun.toSun = glm::normalize(glm::vec3(0.6f, 0.7f, 0.35f));
    s.sun.intensity = 3.0f;
    s.exposure = 1.0f;
    b.view("overview", {24, 20, 24}, {-1, 0, -1}, 50.0f);
    b.view("courtyard", {4.0f, 1.7f, 2.0f}, {-7.0f, 1.3f, 0.0f}, 65.0f);
    b.view("interior", {-11.5f, 1.7f, -5.4f}, {-7.3f, 1.0f, 0.0f}, 70.0f);
    return s;
}

} // namespace pb::scene
