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

GltfWriter goodTriangle() {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
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

std::filesystem::path compressedFile(const std::string& kind) {
    return pb::test::testDataDir() / "gltf" / ("cornell_" + kind + ".glb");
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
    GltfWriter w = goodTriangle();
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
    GltfWriter w = goodTriangle();
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
    GltfWriter w = goodTriangle();
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

INSTANTIATE_TEST_SUITE_P(Files, CompressedGltf,
                         ::testing::Values("meshopt", "draco", "quantize"));

TEST(GltfExtensions, CorruptCompressedDataIsOneLineError) {
    for (const char* kind : {"meshopt", "draco"}) {
        std::vector<unsigned char> bytes = readBytes(compressedFile(kind));
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
