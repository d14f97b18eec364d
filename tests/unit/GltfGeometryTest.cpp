// glTF geometry: hierarchy and transforms, index types, strides, generated normals, .glb.
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;

namespace {

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

} // namespace

TEST(GltfGeometry, HierarchyWithMatrixAndTrs) {
    GltfWriter w;
    const int mesh = w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    // parent: matrix translating by (10, 0, 0); child: TRS = translate (0, 5, 0), 90 degrees
    // about +Y, scale 2.
    const float s = std::sqrt(0.5f);
    const int child = w.addNode({{"name", "child"},
                                 {"mesh", mesh},
                                 {"translation", {0, 5, 0}},
                                 {"rotation", {0, s, 0, s}},
                                 {"scale", {2, 2, 2}}},
                                false);
    w.addNode({{"name", "parent"},
               {"children", {child}},
               {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1}}});
    const Scene scene = loadGltf(w.write(pb::test::outputDir(), "tree"));
    ASSERT_EQ(scene.instances.size(), 1u);
    const Instance& inst = scene.instances[0];
    EXPECT_EQ(inst.nodeName, "child");
    // (1,0,0) scaled to (2,0,0), turned 90 degrees about +Y to (0,0,-2), moved by (10,5,0).
    expectVec(worldPosition(scene, inst, 1), {10, 5, -2});
    expectVec(worldPosition(scene, inst, 2), {10, 7, 0});
    EXPECT_EQ(scene.name, "tree");
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfGeometry, IndexTypesAndNonIndexed) {
    const auto dir = pb::test::outputDir();
    for (int type : {5121, 5123, 5125}) {
        GltfWriter w;
        const int pos = w.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
        w.addMesh({{"attributes", {{"POSITION", pos}}},
                   {"indices", w.addIndices({0, 1, 2, 2, 1, 3}, type)}});
        w.addNode({{"mesh", 0}});
        const Scene s = loadGltf(w.write(dir, "idx" + std::to_string(type)));
        ASSERT_EQ(s.primitives.size(), 1u);
        EXPECT_EQ(s.primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
    }
    GltfWriter w;
    w.addTriangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}}, {});
    w.addNode({{"mesh", 0}});
    const Scene s = loadGltf(w.write(dir, "flat"));
    EXPECT_EQ(s.primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(s.triangleCount(), 2u);
}

TEST(GltfGeometry, InterleavedAttributesWithByteStride) {
    // position, normal, uv interleaved in 32-byte vertices (stride 32, accessor offsets).
    struct Vertex {
        float p[3], n[3], uv[2];
    };
    const std::vector<Vertex> v = {{{0, 0, 0}, {0, 0, 2}, {0, 0}},
                                   {{1, 0, 0}, {0, 0, 2}, {1, 0}},
                                   {{0, 1, 0}, {0, 0, 2}, {0, 1}}};
    GltfWriter w;
    const int bv = w.addBufferView(v.data(), v.size() * sizeof(Vertex), sizeof(Vertex));
    const int pos = w.addAccessor(bv, 5126, 3, "VEC3", 0);
    const int nrm = w.addAccessor(bv, 5126, 3, "VEC3", 12);
    const int uv = w.addAccessor(bv, 5126, 3, "VEC2", 24);
    w.addMesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}},
               {"indices", w.addIndices({0, 1, 2}, 5121)}});
    w.addNode({{"mesh", 0}});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "strided"));
    const Primitive& p = s.primitives.at(0);
    expectVec(p.positions[2], {0, 1, 0});
    expectVec(p.normals[1], {0, 0, 1}); // normalised on load
    ASSERT_EQ(p.uvs.size(), 3u);
    EXPECT_EQ(p.uvs[1], glm::vec2(1, 0));
    expectVec(p.localBounds.max, {1, 1, 0});
}

TEST(GltfGeometry, NormalsAreGeneratedWhenAbsentAndWhenBroken) {
    GltfWriter w;
    // A quad facing +Z plus a zero-area triangle: smooth normals, no NaN.
    const std::vector<glm::vec3> pos = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    w.addTriangleMesh(pos, {0, 1, 2, 0, 2, 3, 1, 4, 4});
    const int p2 = w.addVec3(pos);
    const int n2 = w.addVec3({{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}}); // one zero
    w.addMesh({{"attributes", {{"POSITION", p2}, {"NORMAL", n2}}},
               {"indices", w.addIndices({0, 1, 2, 0, 2, 3})}});
    w.addNode({{"mesh", 0}});
    w.addNode({{"mesh", 1}});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "normals"));
    ASSERT_EQ(s.primitives.size(), 2u);
    for (const Primitive& p : s.primitives)
        for (size_t i = 0; i < 4; ++i)
            expectVec(p.normals[i], {0, 0, 1});
    for (const glm::vec3& n : s.primitives[0].normals)
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    ASSERT_EQ(s.warnings.size(), 1u); // the zero normal, regenerated
    EXPECT_NE(s.warnings[0].find("normals"), std::string::npos);
}

TEST(GltfGeometry, MeshUsedTwiceIsStoredOnce) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    w.addNode({{"name", "a"}, {"mesh", 0}});
    w.addNode({{"name", "b"}, {"mesh", 0}, {"translation", {0, 0, 3}}});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "twice"));
    EXPECT_EQ(s.primitives.size(), 1u);
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].primitive, s.instances[1].primitive);
    EXPECT_EQ(s.triangleCount(), 2u);
    EXPECT_NEAR(s.worldBounds().max.z, 3.0f, 1e-6f);
}

TEST(GltfGeometry, GlbLoadsLikeGltf) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    w.addNode({{"mesh", 0}, {"translation", {1, 2, 3}}});
    const auto dir = pb::test::outputDir();
    const Scene a = loadGltf(w.write(dir, "same"));
    const Scene b = loadScene(w.write(dir, "same", true));
    EXPECT_EQ(b.sourcePath, (dir / "same.glb").string());
    ASSERT_EQ(b.instances.size(), 1u);
    expectVec(worldPosition(b, b.instances[0], 2), worldPosition(a, a.instances[0], 2));
    expectVec(worldPosition(b, b.instances[0], 2), {1, 3, 3});
}

TEST(GltfGeometry, NodesWithoutAScenesArrayAreAllRoots) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2});
    const int child = w.addNode({{"mesh", 0}}, false);
    w.addNode({{"children", {child}}, {"translation", {0, 1, 0}}}, false);
    w.doc.erase("scenes");
    w.doc.erase("scene");
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "noscenes"));
    ASSERT_EQ(s.instances.size(), 1u);
    expectVec(worldPosition(s, s.instances[0], 0), {0, 1, 0});
}
