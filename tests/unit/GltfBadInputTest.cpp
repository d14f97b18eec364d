// Broken glTF files: each gives one pb::Error line "path: problem", never a crash or a hang.
// Every case starts from a good file written at run time and breaks one thing.
#include "core/Error.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;

namespace {

GltfWriter goodTriangle() {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"name", "n"}, {"mesh", 0}});
    return w;
}

// Loads `path`, expects a one-line pb::Error starting with "path: " and containing `problem`.
void expectLoadError(const std::string& path, const std::string& problem) {
    try {
        loadGltf(path);
        ADD_FAILURE() << path << " loaded; expected an error containing: " << problem;
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find(problem), std::string::npos) << msg;
    }
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    GltfWriter::writeBytes(path, text.data(), text.size());
}

} // namespace

TEST(GltfBadInput, MissingFile) {
    expectLoadError((pb::test::outputDir() / "nothing.gltf").string(), "not found");
}

TEST(GltfBadInput, MalformedJson) {
    const auto path = pb::test::outputDir() / "broken.gltf";
    writeText(path, "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    expectLoadError(path.string(), "malformed JSON: parse error at line 1");
}

TEST(GltfBadInput, NotGltfAtAll) {
    const auto path = pb::test::outputDir() / "hello.gltf";
    writeText(path, "[1, 2, 3]");
    expectLoadError(path.string(), "not a JSON object");
}

TEST(GltfBadInput, TruncatedBin) {
    const auto dir = pb::test::outputDir();
    const std::string path = goodTriangle().write(dir, "short");
    std::filesystem::resize_file(dir / "short.bin", 20);
    expectLoadError(path, "short.bin");
}

TEST(GltfBadInput, TruncatedGlb) {
    const auto dir = pb::test::outputDir();
    const std::string path = goodTriangle().write(dir, "short", true);
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 16);
    expectLoadError(path, "truncated GLB");
}

TEST(GltfBadInput, IndexOutOfRange) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 7}, "tri");
    w.addNode({{"mesh", 0}});
    expectLoadError(w.write(pb::test::outputDir(), "badindex"),
                    "index 7 out of range (3 vertices) in mesh 'tri'");
}

TEST(GltfBadInput, NanAndInfinitePositions) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const auto dir = pb::test::outputDir();
    for (float bad : {nan, inf}) {
        GltfWriter w;
        w.addTriangleMesh({{0, 0, 0}, {1, bad, 0}, {0, 1, 0}}, {0, 1, 2}, "tri");
        w.addNode({{"mesh", 0}});
        expectLoadError(w.write(dir, std::isnan(bad) ? "nan" : "inf"),
                        "NaN or infinite position (vertex 1) in mesh 'tri'");
    }
}

TEST(GltfBadInput, NanTexCoord) {
    GltfWriter w;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    w.addMesh({{"attributes",
                {{"POSITION", w.addVec3(pb::test::triangleXY())},
                 {"TEXCOORD_0", w.addVec2({{0, 0}, {nan, 0}, {0, 1}})}}}},
              "tri");
    w.addNode({{"mesh", 0}});
    expectLoadError(w.write(pb::test::outputDir(), "nanuv"),
                    "NaN or infinite TEXCOORD_0 (vertex 1) in mesh 'tri'");
}

TEST(GltfBadInput, CyclicNodesAndSecondParents) {
    const auto dir = pb::test::outputDir();
    GltfWriter w = goodTriangle();
    w.addNode({{"name", "a"}, {"children", {2}}});
    w.addNode({{"name", "b"}, {"children", {1}}}, false);
    expectLoadError(w.write(dir, "cycle"), "cyclic node hierarchy: node 'a'");

    GltfWriter self = goodTriangle();
    self.doc["nodes"][0]["children"] = {0};
    expectLoadError(self.write(dir, "self"), "cyclic");

    GltfWriter dag = goodTriangle();
    dag.addNode({{"children", {0}}}); // node 0 is also a root
    expectLoadError(dag.write(dir, "twoparents"), "more than once");
}

TEST(GltfBadInput, NonTrianglePrimitivesAreSkippedWithOneWarning) {
    GltfWriter w = goodTriangle();
    for (int mode : {0, 1, 3, 1}) {
        w.addMesh(
            {{"attributes", {{"POSITION", w.addVec3(pb::test::triangleXY())}}}, {"mode", mode}});
        w.addNode({{"mesh", int(w.doc["meshes"].size()) - 1}});
    }
    const std::string path = w.write(pb::test::outputDir(), "lines");
    const Scene s = loadGltf(path);
    EXPECT_EQ(s.triangleCount(), 1u);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0].rfind(path + ": skipped 4 primitive(s)", 0), 0u) << s.warnings[0];
    EXPECT_NE(s.warnings[0].find("TRIANGLES"), std::string::npos);
}

TEST(GltfBadInput, UnsupportedRequiredExtension) {
    GltfWriter w = goodTriangle();
    w.doc["extensionsUsed"] = {"EXT_meshopt_compression"};
    w.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
    w.doc["extensionsUsed"] = {"KHR_materials_volume"};
    w.doc["extensionsRequired"] = {"KHR_materials_volume"};
    expectLoadError(w.write(pb::test::outputDir(), "volume"),
                    "requires glTF extension KHR_materials_volume, which probebench does not "
                    "support (supported: EXT_meshopt_compression, ");
}

TEST(GltfBadInput, AccessorAndBufferViewRanges) {
    const auto dir = pb::test::outputDir();
    GltfWriter a = goodTriangle();
    a.doc["accessors"][0]["count"] = 4; // one vertex more than its bufferView holds
    expectLoadError(a.write(dir, "acc"), "reach past the end of bufferView");

    GltfWriter b = goodTriangle();
    b.doc["bufferViews"][0]["byteLength"] = 4096; // bufferView longer than the buffer
    expectLoadError(b.write(dir, "bv"), "reaches past the end of buffer");

    GltfWriter c = goodTriangle();
    c.doc["accessors"][0]["count"] = 1ull << 40; // absurd count, product would overflow
    expectLoadError(c.write(dir, "absurd"), "absurd count");

    GltfWriter d = goodTriangle();
    d.doc["accessors"][0]["byteOffset"] = std::numeric_limits<std::uint32_t>::max();
    expectLoadError(d.write(dir, "offset"), "reach past the end of bufferView");

    GltfWriter e = goodTriangle();
    e.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42;
    expectLoadError(e.write(dir, "noacc"), "missing accessor 42");

    GltfWriter f = goodTriangle();
    f.doc["accessors"][0]["type"] = "VEC2";
    expectLoadError(f.write(dir, "type"), "type is VEC2, expected VEC3");
}

TEST(GltfBadInput, DanglingReferences) {
    const auto dir = pb::test::outputDir();
    GltfWriter a = goodTriangle();
    a.doc["nodes"][0]["mesh"] = 9;
    expectLoadError(a.write(dir, "mesh"), "missing mesh 9");

    GltfWriter b = goodTriangle();
    b.doc["scenes"][0]["nodes"] = {5};
    expectLoadError(b.write(dir, "node"), "missing node 5");

    GltfWriter c = goodTriangle();
    c.doc["meshes"][0]["primitives"][0]["material"] = 3;
    expectLoadError(c.write(dir, "material"), "missing material 3");

    GltfWriter d = goodTriangle();
    d.doc["images"] = json::array({{{"bufferView", 0}, {"mimeType", "image/png"}}});
    d.doc["bufferViews"][0]["byteOffset"] = 1 << 20; // the image's bytes are outside the buffer
    expectLoadError(d.write(dir, "image"), "image 0");

    GltfWriter e = goodTriangle();
    e.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectLoadError(e.write(dir, "quat"), "zero quaternion");

    GltfWriter f = goodTriangle();
    f.doc["nodes"][0]["scale"] = {1e30, 1, 1};
    expectLoadError(f.write(dir, "huge"), "absurd world coordinates");
}
