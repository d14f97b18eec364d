// glTF content beyond geometry: materials and textures, KHR_lights_punctual, cameras as
// views, the dynamic flag.
#include "core/Error.h"
#include "image/Image.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <gtest/gtest.h>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;

namespace {

// One triangle per material index given, each on its own root node.
GltfWriter trianglesWithMaterials(const std::vector<int>& materials) {
    GltfWriter w;
    for (int m : materials) {
        json prim = {{"attributes", {{"POSITION", w.addVec3(pb::test::triangleXY())}}}};
        if (m >= 0) prim["material"] = m;
        w.addNode({{"mesh", w.addMesh(prim)}});
    }
    return w;
}

} // namespace

TEST(GltfContent, MaterialFactorsModesAndEmissiveStrength) {
    GltfWriter w = trianglesWithMaterials({0, 1, 2, -1});
    w.doc["materials"] = json::array(
        {{{"name", "paint"},
          {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}}}},
          {"doubleSided", true}},
         {{"name", "lamp"},
          {"emissiveFactor", {1.0, 0.5, 0.0}},
          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}}}},
          {"alphaMode", "MASK"},
          {"alphaCutoff", 0.3}},
         {{"name", "Glass"},
          {"alphaMode", "BLEND"},
          {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0}}}}}});
    w.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    w.doc["extensionsRequired"] = {"KHR_materials_emissive_strength"};
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "materials"));
    ASSERT_EQ(s.materials.size(), 4u); // three + the default for the fourth triangle
    EXPECT_EQ(s.materials[0].name, "paint");
    EXPECT_EQ(s.materials[0].baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    EXPECT_TRUE(s.materials[0].doubleSided);
    EXPECT_EQ(s.materials[1].emissive, glm::vec3(8.0f, 4.0f, 0.0f));
    EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(s.materials[1].alphaCutoff, 0.3f);
    EXPECT_FALSE(s.materials[1].doubleSided);
    EXPECT_TRUE(s.materials[2].invisible());
    EXPECT_FALSE(s.materials[0].invisible());
    // The file has materials, so the glTF default material (single-sided) applies.
    EXPECT_EQ(s.primitives[3].material, 3);
    EXPECT_FALSE(s.materials[3].doubleSided);
}

TEST(GltfContent, WithoutAnyMaterialTheDefaultIsDoubleSided) {
    GltfWriter w = trianglesWithMaterials({-1});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "nomat"));
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_TRUE(s.materials[0].doubleSided);
    EXPECT_EQ(s.primitives[0].material, 0);
}

TEST(GltfContent, TexturesDecodeToRgba8AndAreShared) {
    const auto dir = pb::test::outputDir();
    pb::image::Image8 img;
    img.width = 2;
    img.height = 1;
    img.pixels = {255, 0, 0, 255, 0, 128, 255, 64};
    pb::image::writePng((dir / "tex.png").string(), img);
    GltfWriter w = trianglesWithMaterials({0});
    w.doc["images"] = json::array({{{"uri", "tex.png"}}});
    w.doc["textures"] = json::array({{{"source", 0}}});
    w.doc["materials"] =
        json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                      {"emissiveTexture", {{"index", 0}}},
                      {"emissiveFactor", {1, 1, 1}}}});
    const Scene s = loadGltf(w.write(dir, "textured"));
    ASSERT_EQ(s.textures.size(), 1u); // one image used twice is decoded once
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    EXPECT_EQ(s.materials[0].emissiveTexture, 0);
    EXPECT_EQ(s.textures[0].width, 2);
    EXPECT_EQ(s.textures[0].height, 1);
    EXPECT_EQ(s.textures[0].rgba8, img.pixels);
}

TEST(GltfContent, MissingImageFileWarnsAndDrawsWithoutIt) {
    GltfWriter w = trianglesWithMaterials({0});
    w.doc["images"] = json::array({{{"uri", "missing.png"}}});
    w.doc["textures"] = json::array({{{"source", 0}}});
    w.doc["materials"] =
        json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 1.0, 1.0};
    const std::string path = w.write(pb::test::outputDir(), "noimage");
    const Scene s = loadGltf(path);
    EXPECT_EQ(s.materials[0].baseColorTexture, -1);
    EXPECT_EQ(s.materials[0].baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f)); // the factor alone
    EXPECT_TRUE(s.textures.empty());
    ASSERT_EQ(s.warnings.size(), 1u); // one line, naming the file; not tinygltf's three
    EXPECT_EQ(s.warnings[0].rfind(path + ": ", 0), 0u) << s.warnings[0];
    EXPECT_NE(s.warnings[0].find("missing.png"), std::string::npos) << s.warnings[0];
    EXPECT_EQ(s.warnings[0].find('\n'), std::string::npos);
}

TEST(GltfContent, PunctualLightsAndTheSun) {
    GltfWriter w;
    w.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    w.doc["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({{{"type", "directional"}, {"intensity", 5.0}, {"color", {1.0, 0.9, 0.8}}},
                     {{"type", "point"}, {"intensity", 100.0}, {"range", 10.0}},
                     {{"type", "spot"},
                      {"name", "lamp"},
                      {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}},
                     {{"type", "directional"}, {"intensity", 1.0}}});
    auto lightNode = [&](int light, const json& extra) {
        json n = extra;
        n["extensions"]["KHR_lights_punctual"]["light"] = light;
        return n;
    };
    const float s = std::sqrt(0.5f);
    // -90 degrees about X turns the light's -Z into -Y: the sun shines straight down.
    w.addNode(lightNode(0, {{"rotation", {-s, 0, 0, s}}}));
    w.addNode(lightNode(1, {{"translation", {1, 2, 3}}}));
    w.addNode(lightNode(2, {{"translation", {0, 4, 0}}, {"rotation", {-s, 0, 0, s}}}));
    w.addNode(lightNode(3, json::object()));
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    w.addNode({{"mesh", 0}});
    const Scene sc = loadGltf(w.write(pb::test::outputDir(), "lights"));
    EXPECT_TRUE(sc.sun.enabled);
    EXPECT_NEAR(sc.sun.toSun.y, 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(sc.sun.intensity, 5.0f);
    EXPECT_NEAR(sc.sun.color.z, 0.8f, 1e-6f);
    ASSERT_EQ(sc.lights.size(), 3u);
    EXPECT_EQ(sc.lights[0].type, LightType::Point);
    EXPECT_EQ(sc.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(sc.lights[0].range, 10.0f);
    EXPECT_EQ(sc.lights[1].type, LightType::Spot);
    EXPECT_EQ(sc.lights[1].name, "lamp");
    EXPECT_NEAR(sc.lights[1].direction.y, -1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(sc.lights[1].outerConeAngle, 0.5f);
    EXPECT_EQ(sc.lights[2].type, LightType::Directional); // only the first becomes the sun
}

TEST(GltfContent, WithoutADirectionalLightTheSunAndSkyKeepTheirDefaults) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    w.addNode({{"mesh", 0}});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "nosun"));
    const Scene defaults;
    EXPECT_EQ(s.sun.enabled, defaults.sun.enabled);
    EXPECT_EQ(s.sun.toSun, defaults.sun.toSun);
    EXPECT_EQ(s.sky.radiance, defaults.sky.radiance);
}

TEST(GltfContent, CamerasBecomeViewsAfterTheDefault) {
    GltfWriter w;
    w.doc["cameras"] =
        json::array({{{"type", "perspective"},
                      {"name", "hero"},
                      {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
                     {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}},
                     {{"type", "orthographic"},
                      {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}});
    const float s = std::sqrt(0.5f);
    w.addNode({{"camera", 0}, {"translation", {0, 1, 5}}});
    // Turned 90 degrees about +Y: looks down -X.
    w.addNode({{"name", "side"}, {"camera", 1}, {"rotation", {0, s, 0, s}}});
    w.addNode({{"camera", 2}});
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    w.addNode({{"mesh", 0}});
    const Scene sc = loadGltf(w.write(pb::test::outputDir(), "cameras"));
    ASSERT_EQ(sc.views.size(), 3u); // default, hero, side; the orthographic one warns
    EXPECT_EQ(sc.views[0].name, "default");
    const View& hero = sc.views[1];
    EXPECT_EQ(hero.name, "hero");
    EXPECT_EQ(hero.position, glm::vec3(0, 1, 5));
    EXPECT_NEAR(hero.target.z - hero.position.z, -1.0f, 1e-5f);
    EXPECT_NEAR(hero.fovYDegrees, 0.5f * 180.0f / 3.14159265f, 1e-3f);
    EXPECT_EQ(sc.views[2].name, "side");
    EXPECT_NEAR(glm::normalize(sc.views[2].target - sc.views[2].position).x, -1.0f, 1e-5f);
    EXPECT_EQ(sc.warnings.size(), 1u);
}

TEST(GltfContent, DynamicFromExtrasAndOptionsMovesWholeSubtrees) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    const int leaf = w.addNode({{"name", "wheel"}, {"mesh", 0}}, false);
    w.addNode({{"name", "car"},
               {"children", {leaf}},
               {"extras", {{"dynamic", true}}},
               {"translation", {0, 0, 50}}});
    w.addNode({{"name", "door"}, {"mesh", 0}, {"translation", {0, 0, -20}}});
    w.addNode({{"name", "house"}, {"mesh", 0}});
    const std::string path = w.write(pb::test::outputDir(), "dynamic");
    SceneOptions opts;
    opts.dynamicNodes = {"door"};
    const Scene s = loadGltf(path, opts);
    ASSERT_EQ(s.instances.size(), 3u);
    EXPECT_TRUE(s.instances[0].dynamic);  // wheel, under the dynamic car
    EXPECT_TRUE(s.instances[1].dynamic);  // door, by name
    EXPECT_FALSE(s.instances[2].dynamic); // house
    EXPECT_NEAR(s.staticWorldBounds().min.z, 0.0f, 1e-6f);
    EXPECT_NEAR(s.worldBounds().max.z, 50.0f, 1e-6f);

    opts.dynamicNodes = {"door", "boat", "plane"};
    try {
        loadGltf(path, opts);
        FAIL();
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find("'boat', 'plane'"), std::string::npos) << msg;
        EXPECT_EQ(msg.find("'door'"), std::string::npos) << msg;
    }
}
