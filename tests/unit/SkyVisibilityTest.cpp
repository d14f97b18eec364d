// meanSkyVisibility (SkyVisibility.h): the share of the sky a scene's surfaces see, which sets
// the flat ambient of frames without GI. A closed room sees none, an open floor nearly all, a
// room without a ceiling what its opening's view factor says; the built-in interior and square
// land on their sides of it.
#include "ProbeTestScenes.h"
#include "scene/SceneLoader.h"
#include "scene/SkyVisibility.h"

#include <gtest/gtest.h>

using namespace pb;

namespace {

scene::Scene sceneOf(std::initializer_list<scene::Primitive> prims) {
    scene::Scene s = test::emptyScene();
    for (const scene::Primitive& p : prims)
        test::addInstance(s, p);
    return s;
}

} // namespace

TEST(SkyVisibility, ClosedRoomSeesNoSky) {
    const scene::Scene s = sceneOf({test::boxPrimitive({-2, 0, -2}, {2, 3, 2}, true, 0)});
    EXPECT_EQ(scene::meanSkyVisibility(s), 0.0f);
}

TEST(SkyVisibility, OpenFloorSeesNearlyAllOfIt) {
    scene::Primitive floor;
    test::addQuad(floor, {-10, 0, -10}, {20, 0, 0}, {0, 0, 20}, {0, 1, 0});
    // A small block gives the bounds a height (eyes are drawn inside them) and blocks a little.
    const scene::Scene s =
        sceneOf({floor, test::boxPrimitive({-0.1f, 0, -0.1f}, {0.1f, 0.2f, 0.1f}, false, 0)});
    const float v = scene::meanSkyVisibility(s);
    EXPECT_GT(v, 0.95f);
    EXPECT_LE(v, 1.0f);
}

TEST(SkyVisibility, AFloorAloneSeesAllOfIt) {
    // No height at all: the eyes must still find the floor (from above; its back is not seen).
    scene::Primitive floor;
    test::addQuad(floor, {-10, 0, -10}, {20, 0, 0}, {0, 0, 20}, {0, 1, 0});
    EXPECT_EQ(scene::meanSkyVisibility(sceneOf({floor})), 1.0f);
}

TEST(SkyVisibility, RoomWithoutCeilingSeesItsOpening) {
    // A unit cube room open at the top: the view factor of a cube's face to the opposite face
    // is 0.1998, to an adjacent face 0.2000, so every face sees 0.2 of the sky.
    scene::Primitive room;
    test::addQuad(room, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});
    test::addQuad(room, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0});
    test::addQuad(room, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0});
    test::addQuad(room, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    test::addQuad(room, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1});
    const float v = scene::meanSkyVisibility(sceneOf({room}));
    EXPECT_NEAR(v, 0.2f, 0.03f) << "4096 samples: one standard error is about 0.006";
}

TEST(SkyVisibility, SurfacesOfADoubleSidedPlaneCountOnTheSideTheEyesSee) {
    // A double-sided floor with room above and below: both sides are seen, the top one sees
    // the sky, the bottom one too (nothing below it either).
    scene::Scene s = sceneOf({});
    s.materials[0].doubleSided = true;
    scene::Primitive floor;
    test::addQuad(floor, {-5, 0, -5}, {10, 0, 0}, {0, 0, 10}, {0, 1, 0});
    test::addInstance(s, floor);
    scene::Primitive marker; // bounds below and above the floor
    test::addQuad(marker, {0, -1, 0}, {0.01f, 0, 0}, {0, 0, 0.01f}, {0, 1, 0});
    test::addQuad(marker, {0, 1, 0}, {0.01f, 0, 0}, {0, 0, 0.01f}, {0, -1, 0});
    test::addInstance(s, marker);
    EXPECT_GT(scene::meanSkyVisibility(s), 0.95f);
}

TEST(SkyVisibility, BuiltinInteriorAndSquare) {
    // rooms: a closed house lit through openings; its outer faces are not what anyone sees.
    const scene::Scene rooms = scene::makeBuiltinScene("rooms");
    EXPECT_LT(rooms.sky.visibility, 0.05f);
    EXPECT_EQ(rooms.sky.visibility, scene::meanSkyVisibility(rooms)); // measured at load
    const scene::Scene courtyard = scene::makeBuiltinScene("courtyard");
    EXPECT_GT(courtyard.sky.visibility, 0.5f);
}

TEST(SkyVisibility, SceneWithoutSurfacesSeesNothing) {
    EXPECT_EQ(scene::meanSkyVisibility(test::emptyScene()), 0.0f);
    EXPECT_EQ(scene::meanSkyVisibility(test::emptyScene(), 0), 0.0f);
}
