// Issue 42, item 4: sun leaking along the wall/floor and wall/wall seams of a room the sun
// cannot reach. Two rooms with 2 cm walls and a 2 cm roof stand on open ground; the west room
// has a large window towards the sun, the east room is closed. With the sky black and no other
// light, every pixel of the east room is black in the truth, so any direct light the
// rasterizer puts there is a shadow-map leak. The test reads the radiance target and counts
// lit pixels.
#include "GlTestFixture.h"
#include "frame/FrameRenderer.h"
#include "passes/RenderView.h"
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

class ShadowSeamLeak : public test::GlTest, public ::testing::WithParamInterface<LeakCase> {};

} // namespace

TEST_P(ShadowSeamLeak, AClosedRoomStaysDark) {
    const LeakCase& c = GetParam();
    scene::Scene s = twoThinRooms(c.toSun);
    const scene::View* view = s.findView(c.view);
    ASSERT_NE(view, nullptr);
    const int w = 320, h = 180;
    render::FrameRenderer renderer(s, render::defaultFrameSettings(s));
    renderer.render(render::makeRenderView(*view, s.worldBounds(), w, h));
    const image::ImageF img = renderer.readRadiance();
    checkNoGlErrors("rendering");

    // A lit sun-facing surface here has radiance albedo / pi * 5 = 1.1; the leak lines of the
    // old shadow lookup reached 0.1 to 1.1. 1e-3 leaves room for nothing but rounding.
    int lit = 0;
    float brightest = 0.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float l = std::max({img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)});
            brightest = std::max(brightest, l);
            if (l > 1e-3f) ++lit;
        }
    EXPECT_EQ(lit, 0) << "pixels with sun in the closed room, brightest " << brightest;
}

INSTANTIATE_TEST_SUITE_P(
    Sun, ShadowSeamLeak,
    ::testing::Values(LeakCase{"high_west", {-1.0f, 1.6f, 0.3f}, "partition"},
                      LeakCase{"high_west", {-1.0f, 1.6f, 0.3f}, "corner"},
                      LeakCase{"low_west", {-1.0f, 0.5f, -0.4f}, "partition"},
                      LeakCase{"low_west", {-1.0f, 0.5f, -0.4f}, "corner"},
                      LeakCase{"low_north", {0.3f, 0.4f, 1.0f}, "corner"}),
    [](const auto& info) { return std::string(info.param.name) + "_" + info.param.view; });
