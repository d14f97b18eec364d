// The default view is judged by what it sees (DefaultView.h, checkView): every built-in
// scene, every shared scene and every compressed test file gets a default view that sees
// mostly front faces, with an open depth range, not sky only and not from inside a mesh, and
// (where the scene has any light) much of it lit directly. checkView itself is tested on views
// that must fail, including a closed room whose light is elsewhere.
#include "scene/DefaultView.h"
#include "scene/SceneBuilder.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"

#include <cstdio>
#include <gtest/gtest.h>

using namespace pb::scene;

namespace {

void expectGoodDefaultView(const Scene& s, const std::string& label) {
    ASSERT_FALSE(s.views.empty());
    const View& v = s.views.front();
    const ViewCheck c = checkView(s, v);
    std::printf("[ view     ] %-40s front %.2f back %.2f sky %.2f near %.2f depth median %.2f "
                "centre %.2f lit %.2f%s\n",
                label.c_str(), c.frontFraction, c.backFraction, c.skyFraction, c.nearFraction,
                c.medianDepth, c.centreDepth, c.litFraction,
                c.insideClosedMesh ? " INSIDE A MESH" : "");
    EXPECT_TRUE(c.good()) << label << ": front " << c.frontFraction << ", back "
                          << c.backFraction << ", sky " << c.skyFraction << ", near "
                          << c.nearFraction << ", median depth " << c.medianDepth
                          << ", centre depth " << c.centreDepth
                          << ", inside " << c.insideClosedMesh << ", eye clear " << c.eyeClear;
    EXPECT_GE(c.frontFraction, 0.5f) << label;
    EXPECT_LT(c.skyFraction, 0.5f) << label;
    EXPECT_FALSE(c.insideClosedMesh) << label;
    if (c.sceneHasLight) {
        EXPECT_GE(c.litFraction, 0.1f) << label;
    }
}

View lookFrom(glm::vec3 eye, glm::vec3 target) {
    View v;
    v.position = eye;
    v.target = target;
    return v;
}

} // namespace

TEST(DefaultViewCheck, BuiltinScenes) {
    for (const char* name : {"cornell", "rooms", "courtyard"})
        expectGoodDefaultView(makeBuiltinScene(name), name);
}

TEST(DefaultViewCheck, SharedScenes) {
    PB_REQUIRE_SHARED_SCENES();
    for (const char* file :
         {"cornell_box/CornellBox-Original.gltf", "sponza_decimated/sponza_s_lod4.glb",
          "space_ship_hallway/space_ship_hallway.glb",
          "japanese_bridge_garden/japanese_bridge_garden.gltf",
          "dream_apartment/dream_apartment.gltf"})
        expectGoodDefaultView(loadGltf((pb::test::scenesDir() / file).string()), file);
}

// Issue 42 item 1: a diorama - a city block on a thick solid base that fills most of the
// bounds' height - got a default view inside or under its base (every eye height of the
// interior search lies in the base). Its default view must see the block from outside.
TEST(DefaultViewCheck, ADioramaOnAThickBaseIsSeenFromOutside) {
    Scene s;
    s.name = "diorama";
    SceneBuilder b(s);
    const int stone = b.material("base", {0.5f, 0.5f, 0.5f});
    const int wall = b.material("wall", {0.7f, 0.6f, 0.5f});
    b.box("base", {-5, 0, -4}, {5, 6, 4}, stone);
    b.box("house_a", {-4, 6, -3}, {-1, 8, 0}, wall);
    b.box("house_b", {0.5f, 6, -3.5f}, {3.5f, 9, -1}, wall);
    b.box("house_c", {-2, 6, 1}, {2, 7.5f, 3.5f}, wall);
    s.views.insert(s.views.begin(), makeDefaultView(s));
    expectGoodDefaultView(s, "diorama");
    EXPECT_GT(s.views.front().position.y, 6.0f) << "above the base's top";
}

TEST(DefaultViewCheck, CompressedTestFiles) {
    for (const char* name : {"cornell_meshopt.glb", "cornell_draco.glb", "cornell_quantize.glb",
                             "cornell_meshopt_separate.gltf"}) {
        const auto file = pb::test::testDataDir() / "gltf" / name;
        expectGoodDefaultView(loadGltf(file.string()), file.filename().string());
    }
}

TEST(DefaultViewCheck, BadViewsFail) {
    const Scene s = makeBuiltinScene("cornell");
    // Inside the tall box (a closed box, faces outwards): every ray meets a back face.
    const ViewCheck inside = checkView(s, lookFrom({-0.4f, 0.6f, -0.35f}, {0.5f, 0.6f, -0.35f}));
    EXPECT_TRUE(inside.insideClosedMesh);
    EXPECT_FALSE(inside.good());
    // Far outside, looking away from the scene: sky only.
    const ViewCheck sky = checkView(s, lookFrom({0, 1, 50}, {0, 1, 100}));
    EXPECT_EQ(sky.skyFraction, 1.0f);
    EXPECT_FALSE(sky.good());
    // Nose against a wall: everything near.
    const ViewCheck wall = checkView(s, lookFrom({0, 1, -0.9f}, {0, 1, -2}));
    EXPECT_FALSE(wall.good()) << wall.nearFraction;
}

// The Cornell box is lit only by its ceiling panel: its classic view sees the panel and walls
// the panel reaches. The same box with the panel's light moved into a closed box of its own
// (a point light sealed away, the panel dark) still has a light, but nothing the view sees
// receives it: the view fails, on light alone.
TEST(DefaultViewCheck, AViewMustSeeSurfacesTheLightReaches) {
    Scene s = makeBuiltinScene("cornell");
    View front;
    for (const View& v : s.views)
        if (v.name == "front") front = v;
    ASSERT_EQ(front.name, "front");
    const ViewCheck lit = checkView(s, front);
    EXPECT_TRUE(lit.sceneHasLight);
    EXPECT_GT(lit.litFraction, 0.5f);
    EXPECT_TRUE(lit.good());
    for (Material& m : s.materials)
        m.emissive = glm::vec3(0.0f);
    Light sealed;
    sealed.position = {-0.4f, 0.6f, -0.35f}; // inside the tall box (closed, faces outwards)
    sealed.intensity = 10.0f;
    s.lights.push_back(sealed);
    const ViewCheck dark = checkView(s, front);
    EXPECT_TRUE(dark.sceneHasLight);
    EXPECT_EQ(dark.litFraction, 0.0f);
    EXPECT_FALSE(dark.good());
}
