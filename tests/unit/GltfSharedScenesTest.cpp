// The five real scenes in ../shared/scenes: exact triangle counts and bounds from its
// README, their quirks, and where the default view ends up. Prints load times (information
// only: tests never assert a wall time).
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/SceneRaycast.h"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>

using namespace pb::scene;

namespace {

struct SharedScene {
    const char* file;
    std::size_t triangles;
    glm::vec3 min, max; // world bounds from shared/scenes/README.md
};

const SharedScene kScenes[] = {
    {"cornell_box/CornellBox-Original.gltf", 32, {-1.02f, 0, -1.04f}, {1.00f, 1.99f, 0.99f}},
    {"sponza_decimated/sponza_s_lod4.glb",
     187364,
     {-16.25f, -1.13f, -9.40f},
     {20.0f, 18.76f, 10.40f}},
    {"space_ship_hallway/space_ship_hallway.glb",
     53400,
     {15.88f, -3.08f, -25.58f},
     {24.35f, 3.92f, 3.58f}},
    {"japanese_bridge_garden/japanese_bridge_garden.gltf",
     21883,
     {-5.53f, 0.38f, -5.26f},
     {5.83f, 7.39f, 6.10f}},
    {"dream_apartment/dream_apartment.gltf",
     177934,
     {0.44f, -0.10f, -11.43f},
     {12.81f, 2.68f, -0.13f}},
};

// Test names and failure messages show the file, not the struct's bytes.
void PrintTo(const SharedScene& s, std::ostream* os) {
    *os << s.file;
}

Scene load(const std::string& relative) {
    return loadScene((pb::test::scenesDir() / relative).string());
}

class GltfSharedScenes : public ::testing::TestWithParam<SharedScene> {};

} // namespace

TEST_P(GltfSharedScenes, TriangleCountBoundsAndDefaultView) {
    PB_REQUIRE_SHARED_SCENES();
    const SharedScene& e = GetParam();
    const auto start = std::chrono::steady_clock::now();
    const Scene s = load(e.file);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(s.triangleCount(), e.triangles);
    const Bounds b = s.worldBounds();
    // Within 1% of the scene's size (the README rounds to centimetres).
    const float tol = 0.01f * glm::length(glm::vec3(e.max - e.min));
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(b.min[a], e.min[a], tol) << "axis " << a;
        EXPECT_NEAR(b.max[a], e.max[a], tol) << "axis " << a;
    }
    // Material extensions probebench ignores (japanese_bridge_garden: KHR_materials_ior,
    // KHR_materials_specular) are announced once each; anything else is unexpected.
    for (const std::string& w : s.warnings)
        if (w.find(", which probebench ignores") == std::string::npos)
            ADD_FAILURE() << "unexpected warning: " << w;

    // The default view stands inside the bounds; report what it looks at (free distance along
    // its centre ray and the share of a 9x9 grid of view rays that hit something).
    ASSERT_FALSE(s.views.empty());
    const View& v = s.views.front();
    EXPECT_EQ(v.name, "default");
    for (int a = 0; a < 3; ++a) {
        EXPECT_GT(v.position[a], b.min[a]);
        EXPECT_LT(v.position[a], b.max[a]);
    }
    const pb::test::SceneRaycaster rc(s);
    const glm::vec3 f = glm::normalize(v.target - v.position);
    const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0))), u = glm::cross(r, f);
    const float th = std::tan(glm::radians(v.fovYDegrees) * 0.5f);
    int hits = 0;
    for (int y = -4; y <= 4; ++y)
        for (int x = -4; x <= 4; ++x)
            hits +=
                rc.hits(v.position, f + (x / 4.0f) * th * 16.0f / 9.0f * r + (y / 4.0f) * th * u);
    const double centre = rc.cast(v.position, f);
    std::printf("[ scene    ] %-52s %7.1f ms  %zu tris  default view pos (%.2f, %.2f, %.2f) "
                "target (%.2f, %.2f, %.2f)  centre ray free %.2f m  hits %d/81\n",
                e.file, ms, s.triangleCount(), v.position.x, v.position.y, v.position.z, v.target.x,
                v.target.y, v.target.z, centre, hits);
    // Not staring at a wall from up close: the centre ray travels a tenth of the scene or more.
    EXPECT_GT(centre, 0.1 * double(glm::length(b.size())));
}

INSTANTIATE_TEST_SUITE_P(Shared, GltfSharedScenes, ::testing::ValuesIn(kScenes),
                         [](const auto& info) {
                             std::string n = info.param.file;
                             n = n.substr(0, n.find('/'));
                             return n;
                         });

TEST(GltfSharedSceneQuirks, SpaceShipGlassIsInvisible) {
    PB_REQUIRE_SHARED_SCENES();
    const Scene s = load("space_ship_hallway/space_ship_hallway.glb");
    int glass = 0, emissive = 0;
    for (const Material& m : s.materials) {
        if (m.name == "Glass") {
            ++glass;
            EXPECT_TRUE(m.invisible());
        } else {
            EXPECT_FALSE(m.invisible()) << m.name;
        }
        emissive += glm::length(m.emissive) > 0.0f;
    }
    EXPECT_EQ(glass, 1);
    EXPECT_GE(emissive, 2); // Wall_blue and Vent_light
}

TEST(GltfSharedSceneQuirks, SponzaGetsGeneratedNormalsAndADoubleSidedDefaultMaterial) {
    PB_REQUIRE_SHARED_SCENES();
    const Scene s = load("sponza_decimated/sponza_s_lod4.glb");
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_TRUE(s.materials[0].doubleSided);
    for (const Primitive& p : s.primitives) {
        ASSERT_EQ(p.normals.size(), p.positions.size());
        EXPECT_TRUE(p.uvs.empty());
        for (const glm::vec3& n : p.normals) {
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
        }
    }
}

TEST(GltfSharedSceneQuirks, CornellLightAndGardenEmissiveLanterns) {
    PB_REQUIRE_SHARED_SCENES();
    const Scene cornell = load("cornell_box/CornellBox-Original.gltf");
    bool light = false;
    for (const Material& m : cornell.materials)
        if (m.name == "Light") light = m.emissive == glm::vec3(1.0f);
    EXPECT_TRUE(light);
    const Scene garden = load("japanese_bridge_garden/japanese_bridge_garden.gltf");
    int emissive = 0;
    for (const Material& m : garden.materials)
        emissive += glm::length(m.emissive) > 0.0f;
    EXPECT_EQ(emissive, 1);
    EXPECT_EQ(garden.materials.size(), 13u);
}
