// glTF extensions: a required one probebench cannot honour is one error line naming it and
// the supported ones, found before tinygltf reads any buffer; used-only ones that are ignored
// give one warning each; the compressed test files load like their uncompressed source.
#include "core/Error.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;

namespace {

GltfWriter gltfExtensionsGoodTriangle() {
    GltfWriter w;
    // Non-indexed: GCC 12 warns falsely (-Wstringop-overflow) when addIndices is inlined here.
    w.addTriangleMesh(pb::test::triangleXY(), {}, "tri");
    w.addNode({{"name", "n"}, {"mesh", 0}});
    return w;
}

std::string loadError(const std::string& path, const SceneOptions& options = {}) {
    try {
        loadGltf(path, options);
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "";
}

std::filesystem::path compressedFile(const std::string& name) {
    return pb::test::testDataDir() / "gltf" / name;
}

std::filesystem::path cornellSource() {
    return pb::test::scenesDir() / "cornell_box" / "CornellBox-Original.gltf";
}

std::vector<unsigned char> readBytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace

TEST(GltfExtensions, SupportedListIsSortedAndNamesTheDecoders) {
    const auto& s = supportedGltfExtensions();
    EXPECT_TRUE(std::is_sorted(s.begin(), s.end()));
    for (const char* ext : {"EXT_meshopt_compression", "KHR_draco_mesh_compression",
                            "KHR_mesh_quantization", "KHR_texture_transform",
                            "KHR_materials_emissive_strength", "KHR_lights_punctual"})
        EXPECT_NE(std::find(s.begin(), s.end(), ext), s.end()) << ext;
}

TEST(GltfExtensions, EveryUnsupportedRequiredExtensionIsNamedOnOneLine) {
    GltfWriter w = gltfExtensionsGoodTriangle();
    w.doc["extensionsUsed"] = {"KHR_materials_volume", "EXT_x", "KHR_mesh_quantization"};
    w.doc["extensionsRequired"] = {"KHR_materials_volume", "EXT_x", "KHR_mesh_quantization"};
    const std::string path = w.write(pb::test::outputDir(), "two");
    const std::string msg = loadError(path);
    EXPECT_EQ(msg.rfind(path + ": requires glTF extensions KHR_materials_volume, EXT_x, which "
                               "probebench does not support (supported: ",
                        0),
              0u)
        << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find("KHR_draco_mesh_compression"), std::string::npos) << msg;
}

TEST(GltfExtensions, CheckedBeforeTinygltfReadsBuffers) {
    // A meshopt-style file whose second buffer has no URI: tinygltf alone would fail with
    // "'uri' is missing"; the required extension is named first.
    GltfWriter w = gltfExtensionsGoodTriangle();
    w.doc["extensionsRequired"] = {"EXT_meshopt_compression_v2"};
    const std::string path = w.write(pb::test::outputDir(), "early");
    std::string text;
    {
        json d = json::parse(readBytes(path));
        d["buffers"].push_back({{"byteLength", 4096}});
        text = d.dump();
    }
    GltfWriter::writeBytes(path, text.data(), text.size());
    const std::string msg = loadError(path);
    EXPECT_NE(msg.find("requires glTF extension EXT_meshopt_compression_v2, which"),
              std::string::npos)
        << msg;
}

TEST(GltfExtensions, IgnoredUsedExtensionsWarnOnceEach) {
    GltfWriter w = gltfExtensionsGoodTriangle();
    w.doc["extensionsUsed"] = {"KHR_materials_sheen", "KHR_materials_sheen", "EXT_y",
                               "KHR_mesh_quantization"};
    const std::string path = w.write(pb::test::outputDir(), "used");
    const Scene s = loadGltf(path);
    ASSERT_EQ(s.warnings.size(), 2u);
    EXPECT_EQ(s.warnings[0], path + ": uses glTF extension KHR_materials_sheen, which "
                                    "probebench ignores");
    EXPECT_EQ(s.warnings[1], path + ": uses glTF extension EXT_y, which probebench ignores");
}

// Each compressed test file (tests/data/gltf, made with gltf-transform from the shared
// Cornell box, tests/data/gltf/README.md) has the source's triangles in the same place.
class CompressedGltf : public ::testing::TestWithParam<const char*> {};

TEST_P(CompressedGltf, LoadsLikeItsSource) {
    PB_REQUIRE_SHARED_SCENES();
    const std::filesystem::path file = compressedFile(GetParam());
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const Scene src = loadGltf(cornellSource().string());
    const Scene s = loadGltf(file.string());
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_EQ(s.triangleCount(), src.triangleCount());
    const Bounds a = src.worldBounds(), b = s.worldBounds();
    const float tol = 1e-3f * glm::length(a.size()); // quantization to 14-16 bits
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(a.min[k], b.min[k], tol) << k;
        EXPECT_NEAR(a.max[k], b.max[k], tol) << k;
    }
    ASSERT_EQ(s.materials.size(), src.materials.size());
    for (size_t i = 0; i < s.materials.size(); ++i)
        EXPECT_EQ(s.materials[i].emissive, src.materials[i].emissive) << i;
}

// cornell_meshopt_separate.gltf is the second case: a .gltf whose fallback buffer has
// no uri (tinygltf alone: "'uri' is missing from non binary glTF file buffer").
INSTANTIATE_TEST_SUITE_P(Files, CompressedGltf,
                         ::testing::Values("cornell_meshopt.glb", "cornell_draco.glb",
                                           "cornell_quantize.glb",
                                           "cornell_meshopt_separate.gltf"));

TEST(GltfExtensions, CorruptCompressedDataIsOneLineError) {
    for (const char* kind : {"meshopt", "draco"}) {
        std::vector<unsigned char> bytes =
            readBytes(compressedFile(std::string("cornell_") + kind + ".glb"));
        ASSERT_GT(bytes.size(), 2000u) << kind;
        // Past the JSON chunk: the BIN chunk's compressed streams, zeroed.
        const std::uint32_t jsonLength = bytes[12] | bytes[13] << 8 | bytes[14] << 16;
        for (std::size_t i = 20 + jsonLength + 8; i < bytes.size(); ++i)
            bytes[i] = 0xA5;
        const auto path = pb::test::outputDir() / (std::string(kind) + "_corrupt.glb");
        GltfWriter::writeBytes(path, bytes.data(), bytes.size());
        const std::string msg = loadError(path.string());
        EXPECT_EQ(msg.rfind(path.string() + ": ", 0), 0u) << kind << ": " << msg;
        EXPECT_NE(msg.find("corrupt"), std::string::npos) << kind << ": " << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
}

namespace {

// A triangle with UVs (0,0), (1,0), (0,1) and material 0 whose base colour texture has
// `transform` as its KHR_texture_transform (the image file need not exist: UVs are what is
// tested, and the missing image only warns).
GltfWriter uvTriangle(const json& transform) {
    GltfWriter w;
    const int pos = w.addVec3(pb::test::triangleXY());
    const int uv = w.addVec2({{0, 0}, {1, 0}, {0, 1}});
    w.addMesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"material", 0}});
    w.addNode({{"mesh", 0}});
    w.doc["extensionsUsed"] = {"KHR_texture_transform"};
    w.doc["images"] = json::array({{{"uri", "absent.png"}}});
    w.doc["textures"] = json::array({{{"source", 0}}});
    json info = {{"index", 0}};
    if (!transform.is_null()) info["extensions"]["KHR_texture_transform"] = transform;
    w.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", info}}}}});
    return w;
}

} // namespace

TEST(GltfExtensions, HugeMeshoptFallbackIsRefusedBeforeAllocating) {
    const auto dir = pb::test::outputDir();
    for (const char* f : {"cornell_meshopt_separate.gltf", "cornell_meshopt_separate.bin"})
        std::filesystem::copy_file(compressedFile(f), dir / f);
    const auto path = dir / "cornell_meshopt_separate.gltf";
    json d = json::parse(readBytes(path));
    d["buffers"][1]["byteLength"] = 1ull << 40; // a TiB of zeros if believed
    const std::string text = d.dump();
    GltfWriter::writeBytes(path, text.data(), text.size());
    const std::string msg = loadError(path.string());
    EXPECT_NE(msg.find("fallback buffers declare more than 1024 MiB"), std::string::npos) << msg;
}

TEST(GltfExtensions, TextureTransformIsAppliedToTheUvs) {
    // The extension's example: offset, then rotation by 90 degrees, then scale.
    const json t = {{"offset", {0.5, 0.25}}, {"rotation", 1.57079632679}, {"scale", {2.0, 3.0}}};
    const Scene s = loadGltf(uvTriangle(t).write(pb::test::outputDir(), "tt"));
    ASSERT_EQ(s.primitives.size(), 1u);
    const auto& uv = s.primitives[0].uvs;
    ASSERT_EQ(uv.size(), 3u);
    // u' = cos*sx*u + sin*sy*v + ox; v' = -sin*sx*u + cos*sy*v + oy
    EXPECT_NEAR(uv[0].x, 0.5f, 1e-5f);
    EXPECT_NEAR(uv[0].y, 0.25f, 1e-5f);
    EXPECT_NEAR(uv[1].x, 0.5f, 1e-5f);  // (1,0): x = 0*2 + 0.5
    EXPECT_NEAR(uv[1].y, -1.75f, 1e-5f); // y = -1*2 + 0.25
    EXPECT_NEAR(uv[2].x, 3.5f, 1e-5f);  // (0,1): x = 1*3 + 0.5
    EXPECT_NEAR(uv[2].y, 0.25f, 1e-5f);

    const Scene plain = loadGltf(uvTriangle(json()).write(pb::test::outputDir(), "plain"));
    EXPECT_EQ(plain.primitives[0].uvs[1], glm::vec2(1.0f, 0.0f));
}

// The direction of the rotation, from the extension's own example: "offset [0, 1], rotation
// 90 degrees, scale 0.5 uses only the lower left quadrant of the image, rotated clockwise".
// The unit triangle must land inside u in [0, 0.5], v in [0.5, 1] (the README's GLSL literal,
// read column by column, would put it outside the image).
TEST(GltfExtensions, TextureTransformRotatesAsTheExtensionsExample) {
    const json t = {{"offset", {0.0, 1.0}}, {"rotation", 1.57079632679}, {"scale", {0.5, 0.5}}};
    const Scene s = loadGltf(uvTriangle(t).write(pb::test::outputDir(), "tt_example"));
    for (const glm::vec2& uv : s.primitives[0].uvs) {
        EXPECT_GE(uv.x, -1e-5f);
        EXPECT_LE(uv.x, 0.5f + 1e-5f);
        EXPECT_GE(uv.y, 0.5f - 1e-5f);
        EXPECT_LE(uv.y, 1.0f + 1e-5f);
    }
}

TEST(GltfExtensions, BasisuTexturesWithoutFallbackWarnOnce) {
    GltfWriter w = uvTriangle(json());
    w.doc["extensionsUsed"] = {"KHR_texture_basisu"};
    w.doc["images"] = json::array({{{"uri", "a.ktx2"}, {"mimeType", "image/ktx2"}}});
    w.doc["textures"] = json::array({{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}},
                                     {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}});
    w.doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
    w.doc["materials"][0]["emissiveFactor"] = {1, 1, 1};
    const auto dir = pb::test::outputDir();
    const std::string path = w.write(dir, "basisu");
    GltfWriter::writeBytes(dir / "a.ktx2", "\xABKTX 20\xBB", 8); // present, never decoded
    const Scene s = loadGltf(path);
    EXPECT_EQ(s.materials[0].baseColorTexture, -1);
    EXPECT_EQ(s.materials[0].emissiveTexture, -1);
    int basisu = 0;
    for (const auto& warning : s.warnings)
        basisu += warning.find("KHR_texture_basisu") != std::string::npos;
    EXPECT_EQ(basisu, 1) << ::testing::PrintToString(s.warnings);
}
