// Scene.cpp queries, normal generation and the default-view rule, on hand-made scenes.
#include "scene/DefaultView.h"
#include "scene/MeshOps.h"
#include "scene/Scene.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace pb::scene;

namespace {

Primitive unitCubeCorners() { // two triangles are enough for bounds
    Primitive p;
    p.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, 1}, {-1, 1, 1}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.normals.assign(4, glm::vec3(0, 1, 0));
    p.localBounds = computeBounds(p.positions);
    return p;
}

void sceneBasicsExpectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

} // namespace

TEST(SceneBasics, BoundsFollowInstancesAndSkipDynamicForStatic) {
    Scene s;
    s.materials.emplace_back();
    s.primitives.push_back(unitCubeCorners());
    s.instances.push_back({"a", 0, glm::translate(glm::mat4(1.0f), {10, 0, 0}), false});
    s.instances.push_back({"b", 0, glm::scale(glm::mat4(1.0f), {1, 2, 3}), false});
    s.instances.push_back({"moving", 0, glm::translate(glm::mat4(1.0f), {0, 100, 0}), true});
    const Bounds all = s.worldBounds(), stat = s.staticWorldBounds();
    sceneBasicsExpectVec(all.min, {-1, -2, -3});
    sceneBasicsExpectVec(all.max, {11, 101, 3});
    sceneBasicsExpectVec(stat.min, {-1, -2, -3});
    sceneBasicsExpectVec(stat.max, {11, 2, 3});
    EXPECT_EQ(s.triangleCount(), 6u);
}

TEST(SceneBasics, RotatedInstanceBoundsAreTightNotTheBoxOfTheBox) {
    Scene s;
    s.materials.emplace_back();
    Primitive p;
    p.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    p.indices = {0, 1, 2};
    p.localBounds = computeBounds(p.positions);
    s.primitives.push_back(p);
    s.instances.push_back(
        {"r", 0, glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), {0, 1, 0}), false});
    const Bounds b = s.worldBounds();
    const float r = std::sqrt(0.5f); // the rotated corners of the local box would give ~1.41
    EXPECT_NEAR(b.max.x, r, 1e-5f);
    EXPECT_NEAR(b.min.x, -r, 1e-5f);
    EXPECT_NEAR(b.max.z, r, 1e-5f);
}

TEST(SceneBasics, EmptySceneHasEmptyBounds) {
    Scene s;
    EXPECT_TRUE(s.worldBounds().empty());
    EXPECT_EQ(s.triangleCount(), 0u);
    EXPECT_EQ(s.worldBounds().size(), glm::vec3(0.0f));
}

TEST(SceneBasics, FindViewAndWorldPosition) {
    Scene s;
    s.views.push_back({"default", {}, {0, 0, -1}, 60});
    s.views.push_back({"front", {1, 2, 3}, {0, 0, 0}, 45});
    ASSERT_NE(s.findView("front"), nullptr);
    EXPECT_EQ(s.findView("front")->fovYDegrees, 45.0f);
    EXPECT_EQ(s.findView("nope"), nullptr);
    s.primitives.push_back(unitCubeCorners());
    const Instance inst{"a", 0, glm::translate(glm::mat4(1.0f), {5, 6, 7}), false};
    sceneBasicsExpectVec(worldPosition(s, inst, 2), {6, 7, 8});
}

TEST(SceneBasics, SmoothNormalsAreUnitAndSurviveDegenerateTriangles) {
    Primitive p;
    // A quad in the XZ plane wound counter-clockwise seen from +Y, plus a zero-area triangle
    // and a vertex that no triangle uses.
    p.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
    p.indices = {0, 1, 2, 0, 2, 3, 3, 4, 4};
    generateSmoothNormals(p);
    ASSERT_EQ(p.normals.size(), p.positions.size());
    for (const glm::vec3& n : p.normals) {
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
    for (int i = 0; i < 4; ++i)
        sceneBasicsExpectVec(p.normals[size_t(i)], {0, 1, 0});
}

TEST(SceneBasics, SmoothNormalsOfTinyAndHugeTrianglesStayFinite) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1e-20f, 0, 0}, {0, 1e-20f, 0},
                   {0, 0, 0}, {1e19f, 0, 0},  {0, 1e19f, 0}};
    p.indices = {0, 1, 2, 3, 4, 5};
    generateSmoothNormals(p);
    for (const glm::vec3& n : p.normals)
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    sceneBasicsExpectVec(p.normals[4], {0, 0, 1});
}

TEST(SceneBasics, DefaultViewStandsInsideLooksAlongTheLongAxisSlightlyDown) {
    Bounds b;
    b.extend(glm::vec3(100, 10, -5));
    b.extend(glm::vec3(140, 14, 5)); // 40 m long in X, far from the origin
    const View v = makeDefaultView(b);
    EXPECT_EQ(v.name, "default");
    EXPECT_GT(v.position.x, b.center().x);
    EXPECT_LT(v.position.x, b.max.x);
    EXPECT_NEAR(v.position.y, 10 + 0.3f * 4, 1e-4f);
    EXPECT_NEAR(v.position.z, 0, 1e-4f);
    const glm::vec3 d = glm::normalize(v.target - v.position);
    EXPECT_LT(d.x, -0.98f);
    EXPECT_LT(d.y, -0.05f); // down, but only slightly
    EXPECT_GT(d.y, -0.25f);

    Bounds empty;
    const View e = makeDefaultView(empty);
    EXPECT_NE(e.position, e.target);
}

TEST(SceneBasics, UniqueViewNames) {
    Scene s;
    s.views.push_back({"default"});
    EXPECT_EQ(uniqueViewName(s, "cam"), "cam");
    EXPECT_EQ(uniqueViewName(s, "default"), "default_2");
    s.views.push_back({"default_2"});
    EXPECT_EQ(uniqueViewName(s, "default"), "default_3");
    EXPECT_EQ(uniqueViewName(s, ""), "view");
}

TEST(SceneBasics, InvisibleMeansBlendWithNoAlpha) {
    Material m;
    EXPECT_FALSE(m.invisible());
    m.alphaMode = AlphaMode::Blend;
    m.baseColor.a = 0.0017f; // space_ship_hallway's Glass
    EXPECT_TRUE(m.invisible());
    m.baseColor.a = 0.5f;
    EXPECT_FALSE(m.invisible());
    m.alphaMode = AlphaMode::Mask;
    m.baseColor.a = 0.0f;
    EXPECT_FALSE(m.invisible());
}
