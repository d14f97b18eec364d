// Issue 42, item 4: sun leaking along the wall/floor and wall/wall seams of a room the sun
// cannot reach. Two rooms with 2 cm walls and a 2 cm roof stand on open ground; the west room
// has a large window towards the sun, the east room is closed. With the sky black and no other
// light, every pixel of the east room is black in the truth, so any direct light the
// rasterizer puts there is a shadow-map leak. The test reads the radiance target and counts
// lit pixels. The same for a room of zero-thickness walls (issue 42's 14-triangle box: single
// faces, normals inward), where the wall that shadows a corner is only its unlit side.
#include "GlTestFixture.h"
#include "frame/FrameRenderer.h"
#include "passes/RenderView.h"
#include "scene/MeshOps.h"
#include "scene/SceneBuilder.h"

#include <gtest/gtest.h>

using namespace pb;

namespace {

// Walls as thin as real content draws them (2 cm), flush at every joint, like the two
// rooms sharing a 2 cm wall. The ground reaches far past the house, level with its floor, so
// the shadow map's texels just outside a wall hold a surface as deep as the floor inside.
scene::Scene twoThinRooms(const glm::vec3& toSun) {
    scene::Scene s;
    s.name = "two_thin_rooms";
    scene::SceneBuilder b(s);
    const int white = b.material("white", {0.7f, 0.7f, 0.7f});
    const float t = 0.02f, h = 2.5f, x = 3.0f, z = 2.0f;
    b.box("ground", {-12, -0.2f, -12}, {12, 0, 12}, white);
    b.box("roof", {-x - t, h, -z - t}, {x + t, h + t, z + t}, white);
    b.box("north", {-x - t, 0, z}, {x + t, h, z + t}, white);
    b.box("south", {-x - t, 0, -z - t}, {x + t, h, -z}, white);
    b.box("east", {x, 0, -z}, {x + t, h, z}, white);
    // The west wall of the sunlit room has a window 2 m wide, 0.6..2.0 m high.
    b.box("west_below", {-x - t, 0, -z}, {-x, 0.6f, z}, white);
    b.box("west_above", {-x - t, 2.0f, -z}, {-x, h, z}, white);
    b.box("west_south", {-x - t, 0.6f, -z}, {-x, 2.0f, -1.0f}, white);
    b.box("west_north", {-x - t, 0.6f, 1.0f}, {-x, 2.0f, z}, white);
    b.box("partition", {-t * 0.5f, 0, -z}, {t * 0.5f, h, z}, white);
    s.sun.enabled = true;
    s.sun.toSun = glm::normalize(toSun);
    s.sun.intensity = 5.0f;
    s.sky.radiance = glm::vec3(0.0f);
    s.exposure = 1.0f;
    // Inside the closed east room: the partition's foot, the north-east corner, the floor.
    b.view("partition", {2.8f, 1.4f, -1.8f}, {0.0f, 0.3f, 1.2f}, 80.0f);
    b.view("corner", {0.3f, 1.8f, -1.8f}, {3.0f, 0.2f, 2.0f}, 80.0f);
    return s;
}

struct LeakCase {
    const char* name;
    glm::vec3 toSun;
    const char* view;
};

void PrintTo(const LeakCase& c, std::ostream* os) { *os << c.name << "/" << c.view; }

// Renders `view` without GI and counts the pixels whose radiance exceeds 1e-3 in any channel
// (room for nothing but rounding: every pixel of these closed rooms is black in the truth).
struct LitPixels {
    int count = 0;
    float brightest = 0.0f;
};

LitPixels litPixels(const scene::Scene& s, const scene::View& view, int w, int h) {
    render::FrameRenderer renderer(s, render::defaultFrameSettings(s));
    renderer.render(render::makeRenderView(view, s.worldBounds(), w, h));
    const image::ImageF img = renderer.readRadiance();
    LitPixels out;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float l = std::max({img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)});
            out.brightest = std::max(out.brightest, l);
            if (l > 1e-3f) ++out.count;
        }
    return out;
}

class ShadowSeamLeak : public test::GlTest, public ::testing::WithParamInterface<LeakCase> {};

} // namespace

TEST_P(ShadowSeamLeak, AClosedRoomStaysDark) {
    const LeakCase& c = GetParam();
    scene::Scene s = twoThinRooms(c.toSun);
    const scene::View* view = s.findView(c.view);
    ASSERT_NE(view, nullptr);
    // A lit sun-facing surface here has radiance albedo / pi * 5 = 1.1; the leak lines of the
    // old shadow lookup reached 0.1 to 1.1.
    const LitPixels lit = litPixels(s, *view, 320, 180);
    checkNoGlErrors("rendering");
    EXPECT_EQ(lit.count, 0) << "pixels with sun in the closed room, brightest " << lit.brightest;
}

INSTANTIATE_TEST_SUITE_P(
    Sun, ShadowSeamLeak,
    ::testing::Values(LeakCase{"high_west", {-1.0f, 1.6f, 0.3f}, "partition"},
                      LeakCase{"high_west", {-1.0f, 1.6f, 0.3f}, "corner"},
                      LeakCase{"low_west", {-1.0f, 0.5f, -0.4f}, "partition"},
                      LeakCase{"low_west", {-1.0f, 0.5f, -0.4f}, "corner"},
                      LeakCase{"low_north", {0.3f, 0.4f, 1.0f}, "corner"}),
    [](const auto& info) { return std::string(info.param.name) + "_" + info.param.view; });

namespace {

// A closed room of single faces whose normals point inward, like issue 42's 14-triangle box; the
// sky black, so every pixel inside is black in the truth. Cases:
//  - "box": the box itself (4 x 3 x 5 m, the default sun, its default view). Its back
//    right corner lies on the room's outline as the sun sees it, where the right wall (edge-on
//    to the sun, its inside facing away) meets the floor and the back wall: half of a
//    receiver's filter taps there read no caster at all, and the floor's bias reached past
//    the wall's foot. The "bright dots".
//  - "partition_foot": a 6 x 3 x 5 m room cut by a single-faced partition facing away from a
//    higher sun; the floor beside its foot sees the sun only through it, millimetres away.
struct ZeroThicknessCase {
    const char* name;
    glm::vec3 size;
    glm::vec3 toSun;
    bool partition;
    glm::vec3 eye, target;
};

void PrintTo(const ZeroThicknessCase& c, std::ostream* os) { *os << c.name; }

scene::Scene zeroThicknessRoom(const ZeroThicknessCase& c) {
    scene::Scene s;
    s.name = "zero_thickness_room";
    scene::SceneBuilder b(s);
    const int white = b.material("white", {0.8f, 0.8f, 0.8f});
    const glm::vec3 half{c.size.x * 0.5f, c.size.y, c.size.z * 0.5f};
    b.box("room", {-half.x, 0.0f, -half.z}, {half.x, half.y, half.z}, white);
    scene::Primitive& room = s.primitives.back(); // turned inside out
    for (glm::vec3& n : room.normals)
        n = -n;
    for (std::size_t i = 0; i + 2 < room.indices.size(); i += 3)
        std::swap(room.indices[i + 1], room.indices[i + 2]);
    if (c.partition) { // x = 0.5, facing -x, away from the sun
        scene::Primitive wall;
        wall.material = white;
        wall.positions = {{0.5f, 0.0f, -half.z}, {0.5f, 0.0f, half.z}, {0.5f, half.y, half.z}, {0.5f, half.y, -half.z}};
        wall.normals.assign(4, glm::vec3(-1.0f, 0.0f, 0.0f));
        wall.uvs.assign(4, glm::vec2(0.0f));
        wall.indices = {0, 1, 2, 0, 2, 3};
        wall.localBounds = scene::computeBounds(wall.positions);
        s.instances.push_back(scene::Instance{"partition", int(s.primitives.size()), glm::mat4(1.0f), false});
        s.primitives.push_back(std::move(wall));
    }
    s.sun.enabled = true;
    s.sun.toSun = glm::normalize(c.toSun);
    s.sun.intensity = 5.0f;
    s.sky.radiance = glm::vec3(0.0f);
    s.exposure = 1.0f;
    b.view(c.name, c.eye, c.target, 60.0f);
    return s;
}

class ShadowZeroThickness : public test::GlTest, public ::testing::WithParamInterface<ZeroThicknessCase> {};

} // namespace

TEST_P(ShadowZeroThickness, TheRoomStaysDark) {
    // On the old shadow lookup (the whole depth bias on the receiver: 1 texel + 1.5 per unit of
    // tan, 1.5 texels of normal offset; filter taps past the outline counted as lit) both views
    // had lit lines along the seams (the box: 243 pixels, the brightest 0.78; its lit floor
    // would be 1.2). Now the casters carry the bias into their back sides
    // (shadow_depth.vert), the taps follow the receiver's plane and skip cleared texels
    // (lighting_direct.frag, sunShadow).
    scene::Scene s = zeroThicknessRoom(GetParam());
    const scene::View* view = s.findView(GetParam().name);
    ASSERT_NE(view, nullptr);
    const LitPixels lit = litPixels(s, *view, 640, 360);
    checkNoGlErrors("rendering");
    EXPECT_EQ(lit.count, 0) << "pixels with sun in the closed room, brightest " << lit.brightest;
}

INSTANTIATE_TEST_SUITE_P(
    Rooms, ShadowZeroThickness,
    ::testing::Values(ZeroThicknessCase{"box", {4.0f, 3.0f, 5.0f}, scene::Sun{}.toSun, false,
                                        {0.0f, 0.9f, 1.75f}, {0.0f, 0.41f, -1.75f}},
                      ZeroThicknessCase{"partition_foot", {6.0f, 3.0f, 5.0f}, {0.6f, 1.0f, 0.1f}, true,
                                        {-2.5f, 1.6f, 2.0f}, {0.5f, 0.0f, -0.5f}}),
    [](const auto& info) { return std::string(info.param.name); });
