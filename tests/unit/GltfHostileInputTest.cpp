// Hostile glTF files (found by hand or by the fuzzers in fuzz/): each used to crash, hang or
// allocate gigabytes; now each gives one pb::Error line "path: problem", or loads.
#include "core/Error.h"
#include "core/FileIO.h"
#include "image/Image.h"
#include "scene/GltfContext.h"
#include "scene/GltfInputChecks.h"
#include "scene/ImageDecode.h"
#include "scene/ImageHeader.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <set>
#include <sys/stat.h>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;

namespace {

GltfWriter gltfHostileInputGoodTriangle() {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"name", "n"}, {"mesh", 0}});
    return w;
}

std::string gltfHostileInputLoadError(const std::string& path) {
    try {
        loadGltf(path);
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        return msg;
    }
    return "(loaded)";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

// A PNG signature and IHDR declaring `w` x `h`, nothing else.
std::vector<std::uint8_t> pngHeader(std::uint32_t w, std::uint32_t h) {
    std::vector<std::uint8_t> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',
                                   0,    0,   0,   13,  'I',  'H',  'D',  'R'};
    for (std::uint32_t v : {w, h})
        for (int s = 24; s >= 0; s -= 8)
            b.push_back(std::uint8_t(v >> s));
    b.insert(b.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0});
    return b;
}

// A GLB with `json` as its only chunk (padded with spaces to 4 bytes).
std::vector<std::uint8_t> glbFromJson(std::string json) {
    while (json.size() % 4)
        json += ' ';
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) {
        for (int s = 0; s < 32; s += 8)
            out.push_back(std::uint8_t(v >> s));
    };
    u32(0x46546C67); // "glTF"
    u32(2);
    u32(std::uint32_t(20 + json.size()));
    u32(std::uint32_t(json.size()));
    u32(0x4E4F534A); // JSON
    out.insert(out.end(), json.begin(), json.end());
    return out;
}

// SOI, SOF0 (8x8, one component), then a DHT whose 16 code counts add up to `codes`.
std::vector<std::uint8_t> jpegWithHuffmanCodes(int codes) {
    std::vector<std::uint8_t> b = {0xFF, 0xD8, 0xFF, 0xC0, 0, 11, 8, 0, 8, 0, 8, 1, 1, 0x11, 0};
    const int length = 2 + 17 + codes;
    b.insert(b.end(), {0xFF, 0xC4, std::uint8_t(length >> 8), std::uint8_t(length), 0x00});
    for (int i = 0; i < 16; ++i) {
        const int n = std::min(255, std::max(0, codes - 255 * i));
        b.push_back(std::uint8_t(n));
    }
    b.insert(b.end(), std::size_t(codes), 0);
    b.insert(b.end(), {0xFF, 0xD9});
    return b;
}

GltfWriter withImage(const std::vector<std::uint8_t>& bytes) {
    GltfWriter w = gltfHostileInputGoodTriangle();
    const int view = w.addBufferView(bytes.data(), bytes.size());
    w.doc["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
    return w;
}

} // namespace

TEST(GltfHostileInput, DeeplyNestedJsonIsRefusedBeforeParsing) {
    // 10^5 levels overflowed the stack in tinygltf's recursive extras conversion (SIGSEGV).
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + std::string(100000, '[') +
        std::string(100000, ']') + "}";
    const auto dir = pb::test::outputDir();
    const std::string gltf = (dir / "deep.gltf").string();
    GltfWriter::writeBytes(gltf, json.data(), json.size());
    EXPECT_CONTAINS(gltfHostileInputLoadError(gltf), "JSON nested more than 128 levels deep");

    const std::string glb = (dir / "deep.glb").string();
    const std::vector<std::uint8_t> bytes = glbFromJson(json);
    GltfWriter::writeBytes(glb, bytes.data(), bytes.size());
    EXPECT_CONTAINS(gltfHostileInputLoadError(glb), "JSON nested more than 128 levels deep");

    // Brackets inside strings are text, not nesting.
    GltfWriter w = gltfHostileInputGoodTriangle();
    w.doc["nodes"][0]["name"] = std::string(1000, '[') + "\\\"{";
    EXPECT_EQ(gltfHostileInputLoadError(w.write(dir, "brackets")), "(loaded)");
}

TEST(GltfHostileInput, GlbWhoseJsonChunkOverrunsTheFile) {
    std::vector<std::uint8_t> bytes = glbFromJson("{\"asset\":{\"version\":\"2.0\"}}");
    bytes[12] = 0xF0; // JSON chunk length far past the end (the header's total still fits)
    const std::string path = (pb::test::outputDir() / "chunk.glb").string();
    GltfWriter::writeBytes(path, bytes.data(), bytes.size());
    EXPECT_CONTAINS(gltfHostileInputLoadError(path), "JSON chunk");
}

TEST(GltfHostileInput, HugeAllZeroAccessorIsRefusedBeforeAllocating) {
    // No bufferView means "all zeros": nothing bounds the count but the loader's limits, and
    // 2^28 - 1 vertices were 6 GB of positions and normals.
    const auto dir = pb::test::outputDir();
    for (std::size_t count : {std::size_t(1) << 26, (std::size_t(1) << 28) - 1}) {
        GltfWriter w = gltfHostileInputGoodTriangle();
        w.doc["accessors"][0].erase("bufferView");
        w.doc["accessors"][0]["count"] = count;
        w.doc["meshes"][0]["primitives"][0].erase("indices");
        EXPECT_CONTAINS(gltfHostileInputLoadError(w.write(dir, "zeros")), "would exceed 1024 MiB");
    }
    // A NORMAL accessor with another count is refused before it is read.
    GltfWriter n = gltfHostileInputGoodTriangle();
    n.doc["accessors"].push_back({{"componentType", 5126}, {"count", 1 << 27}, {"type", "VEC3"}});
    n.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    EXPECT_CONTAINS(gltfHostileInputLoadError(n.write(dir, "normals")),
                    "NORMAL of mesh 'tri' has 134217728");
}

TEST(GltfHostileInput, GeometryBudgetCountsEveryRead) {
    // Many primitives may read one accessor: the budget is charged per read, before allocating.
    tinygltf::Model model;
    Scene scene;
    gltf::Context ctx{"many.gltf", model, scene};
    const std::size_t quarter = gltf::kMaxGeometryBytes / 4;
    for (int i = 0; i < 4; ++i)
        EXPECT_NO_THROW(ctx.reserveGeometry(quarter / 8, 8, "POSITION of mesh 1"));
    try {
        ctx.reserveGeometry(1, 8, "POSITION of mesh 2");
        ADD_FAILURE() << "the fifth read fit";
    } catch (const pb::Error& e) {
        EXPECT_CONTAINS(std::string(e.what()), "many.gltf: POSITION of mesh 2: the scene's vertex");
    }
}

TEST(GltfHostileInput, NodesTimesPrimitivesAreCapped) {
    // 1100 primitives x 1000 nodes in 60 kB of JSON: 1.1 M instances, over the 2^20 cap.
    GltfWriter w = gltfHostileInputGoodTriangle();
    json prims = json::array();
    for (int i = 0; i < 1100; ++i)
        prims.push_back(w.doc["meshes"][0]["primitives"][0]);
    w.doc["meshes"][0]["primitives"] = prims;
    for (int i = 0; i < 999; ++i)
        w.addNode({{"mesh", 0}});
    EXPECT_CONTAINS(gltfHostileInputLoadError(w.write(pb::test::outputDir(), "instances")),
                    "more than 1048576 mesh instances");
}

TEST(GltfHostileInput, ManyCamerasWithOneNameGetUniqueNames) {
    // Each view name was found by a linear search per candidate suffix: O(n^3) for n cameras
    // of one name, a 1.5 MB file with 3*10^4 of them ran for hours.
    GltfWriter w = gltfHostileInputGoodTriangle();
    auto camera = [](const char* name) {
        return json{{"type", "perspective"},
                    {"name", name},
                    {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}};
    };
    w.doc["cameras"] = json::array({camera("c"), camera("c_3")});
    w.addNode({{"camera", 1}}); // takes "c_3" first: the suffixes must skip it
    const int n = 20000;
    for (int i = 0; i < n; ++i)
        w.addNode({{"camera", 0}});
    const Scene s = loadGltf(w.write(pb::test::outputDir(), "cams"));
    ASSERT_EQ(s.views.size(), std::size_t(n + 2));
    std::set<std::string> names;
    for (const View& v : s.views)
        names.insert(v.name);
    EXPECT_EQ(names.size(), s.views.size());
    EXPECT_EQ(s.views[1].name, "c_3");
    EXPECT_EQ(s.views[2].name, "c");
    EXPECT_EQ(s.views[3].name, "c_2");
    EXPECT_EQ(s.views[4].name, "c_4");
    EXPECT_EQ(s.views.back().name, "c_" + std::to_string(n + 1));
}

TEST(GltfHostileInput, ImagesAreCheckedBeforeDecoding) {
    const auto dir = pb::test::outputDir();
    EXPECT_CONTAINS(
        gltfHostileInputLoadError(withImage(pngHeader(60000, 60000)).write(dir, "huge")),
        "image 0: declares 60000x60000 pixels, more than a texture may have");
    EXPECT_CONTAINS(gltfHostileInputLoadError(withImage(pngHeader(16384, 16384)).write(dir, "big")),
                    "image 0: declares 16384x16384");
    const std::vector<std::uint8_t> gif = {'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0};
    EXPECT_CONTAINS(gltfHostileInputLoadError(withImage(gif).write(dir, "gif")),
                    "image 0: not a PNG or JPEG file");
    const std::vector<std::uint8_t> jpegWithoutFrame = {0xFF, 0xD8, 0xFF, 0xDA, 0, 2};
    EXPECT_CONTAINS(gltfHostileInputLoadError(withImage(jpegWithoutFrame).write(dir, "jpeg")),
                    "image 0: corrupt image header (no size)");
    // The fuzzer's JPEG: a Huffman table of 16 x 255 codes overflowed stb_image's 257-byte
    // code-size array (memory corruption in the shipped build: Debian's stb has no check).
    // libjpeg-turbo decodes the textures now and refuses the table.
    EXPECT_CONTAINS(
        gltfHostileInputLoadError(withImage(jpegWithHuffmanCodes(16 * 255)).write(dir, "dht")),
        "image 0: JPEG: Bogus Huffman table definition");
}

TEST(GltfHostileInput, TexturesDecodeToRgba8) {
    // A 3x2 PNG written by pb_image (stb_image_write) and read back through libpng.
    pb::image::Image8 png;
    png.width = 3;
    png.height = 2;
    for (int i = 0; i < 6; ++i)
        png.pixels.insert(png.pixels.end(), {std::uint8_t(40 * i), 7, std::uint8_t(250 - i), 255});
    const auto dir = pb::test::outputDir();
    pb::image::writePng((dir / "t.png").string(), png);
    const std::vector<std::uint8_t> bytes = pb::readFileBytes((dir / "t.png").string());
    Rgba8Image decoded;
    EXPECT_EQ(decodeImageRgba8(bytes.data(), bytes.size(), 16, 100, decoded), "");
    EXPECT_EQ(decoded.width, 3u);
    EXPECT_EQ(decoded.height, 2u);
    EXPECT_EQ(decoded.pixels, png.pixels);
    // Sizes are checked from the decoder's own header before any pixel is allocated.
    EXPECT_NE(decodeImageRgba8(bytes.data(), bytes.size(), 2, 100, decoded), "");
    EXPECT_NE(decodeImageRgba8(bytes.data(), bytes.size(), 16, 5, decoded), "");
    // Cut anywhere before the end chunk (IEND, 12 bytes): an error, never a crash.
    for (std::size_t keep = 0; keep + 12 < bytes.size(); ++keep)
        EXPECT_NE(decodeImageRgba8(bytes.data(), keep, 16, 100, decoded), "") << keep;

    // The 4x4 JPEG of the fuzz seeds (fuzz/make_seeds.py), through libjpeg-turbo.
    const std::vector<std::uint8_t> seed =
        pb::readFileBytes((pb::test::sourceDir() / "tests/data/fuzz-seeds/glb/textured.glb").string());
    const std::string text(seed.begin(), seed.end());
    const std::size_t begin = text.find("\xFF\xD8\xFF"), end = text.rfind("\xFF\xD9");
    ASSERT_TRUE(begin != std::string::npos && end != std::string::npos && end > begin);
    const std::vector<std::uint8_t> jpeg(seed.begin() + std::ptrdiff_t(begin),
                                         seed.begin() + std::ptrdiff_t(end + 2));
    EXPECT_EQ(decodeImageRgba8(jpeg.data(), jpeg.size(), 16, 100, decoded), "");
    EXPECT_EQ(decoded.width, 4u);
    EXPECT_EQ(decoded.height, 4u);
    ASSERT_EQ(decoded.pixels.size(), 64u);
    EXPECT_EQ(decoded.pixels[3], 255); // alpha
    // Truncated: libjpeg fills the missing rows (a warning), or refuses the header; either
    // way a 4x4 image or an error.
    for (std::size_t keep = 0; keep < jpeg.size(); ++keep) {
        const std::string problem = decodeImageRgba8(jpeg.data(), keep, 16, 100, decoded);
        if (problem.empty()) {
            EXPECT_EQ(decoded.pixels.size(), 64u) << keep;
        }
    }
}

TEST(GltfHostileInput, ImageGuardCountsPixelsOverAllImages) {
    // Many image entries may share one small, highly compressed picture: the declared pixels
    // of all of them together are capped before each is decoded.
    tinygltf::Model model;
    gltf::ImageGuard guard{&model, gltf::kMaxTotalImagePixels - 100};
    tinygltf::Image image;
    const std::vector<std::uint8_t> png = pngHeader(16, 16);
    std::string err, warn;
    EXPECT_FALSE(gltf::checkedImageLoader(&image, 3, &err, &warn, 0, 0, png.data(), int(png.size()),
                                          &guard));
    EXPECT_CONTAINS(err, "image 3: the images so far declare more than 268435456 pixels");
}

TEST(GltfHostileInput, ImageHeaderSizes) {
    const std::vector<std::uint8_t> png = pngHeader(640, 480);
    ImageHeader h = readImageHeader(png.data(), png.size());
    EXPECT_EQ(h.kind, ImageHeader::Kind::Png);
    EXPECT_EQ(h.width, 640u);
    EXPECT_EQ(h.height, 480u);
    // SOI, an APP0 segment, fill bytes, then SOF2 (progressive): height 300, width 500.
    const std::vector<std::uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xE0, 0,    4, 1,    2,
                                            0xFF, 0xFF, 0xC2, 0,    11,   8, 0x01, 0x2C,
                                            0x01, 0xF4, 1,    1,    0x11, 0};
    h = readImageHeader(jpeg.data(), jpeg.size());
    EXPECT_EQ(h.kind, ImageHeader::Kind::Jpeg);
    EXPECT_EQ(h.width, 500u);
    EXPECT_EQ(h.height, 300u);
    // Cut-off headers give no size, never a read past the end.
    for (std::size_t keep = 0; keep < 18; ++keep) // the width ends at byte 18
        EXPECT_EQ(readImageHeader(jpeg.data(), keep).width, 0u) << keep;
    for (std::size_t keep = 0; keep < 24; ++keep)
        EXPECT_EQ(readImageHeader(png.data(), keep).width, 0u) << keep;
}

TEST(GltfHostileInput, BufferUriNamingAFifoIsRefusedInsteadOfBlocking) {
    const auto dir = pb::test::outputDir();
    GltfWriter w = gltfHostileInputGoodTriangle();
    const std::string path = w.write(dir, "fifo");
    std::filesystem::remove(dir / "fifo.bin");
    ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
    EXPECT_CONTAINS(gltfHostileInputLoadError(path), "not a regular file");
}

TEST(GltfHostileInput, NamesWithLineBreaksStayOnOneLine) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 9}, "evil\nname\x01");
    w.addNode({{"mesh", 0}});
    EXPECT_CONTAINS(gltfHostileInputLoadError(w.write(pb::test::outputDir(), "names")),
                    "in mesh 'evil\\nname\\x01'");
}

TEST(GltfHostileInput, SparseAccessorsAreRefused) {
    GltfWriter w = gltfHostileInputGoodTriangle();
    w.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 1}, {"componentType", 5125}}},
                                       {"values", {{"bufferView", 0}}}};
    EXPECT_CONTAINS(gltfHostileInputLoadError(w.write(pb::test::outputDir(), "sparse")),
                    "sparse accessors are not supported");
}

TEST(GltfHostileInput, LightsAndCamerasOutOfRange) {
    const auto dir = pb::test::outputDir();
    auto withLight = [&](const json& light, const json& node) {
        GltfWriter w = gltfHostileInputGoodTriangle();
        w.doc["extensionsUsed"] = {"KHR_lights_punctual"};
        w.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({light});
        json n = node;
        n["extensions"]["KHR_lights_punctual"]["light"] = 0;
        w.addNode(n);
        return w;
    };
    EXPECT_CONTAINS(gltfHostileInputLoadError(
                        withLight({{"type", "spot"},
                                   {"spot", {{"innerConeAngle", 0.9}, {"outerConeAngle", 0.5}}}},
                                  json::object())
                            .write(dir, "cone")),
                    "spot cone angles must be 0 <= inner < outer <= pi/2");
    EXPECT_CONTAINS(gltfHostileInputLoadError(
                        withLight({{"type", "point"}, {"color", {1e39, 1, 1}}}, json::object())
                            .write(dir, "colour")),
                    "negative or non-finite colour");
    EXPECT_CONTAINS(
        gltfHostileInputLoadError(
            withLight({{"type", "point"}}, {{"translation", {1e11, 0, 0}}}).write(dir, "far")),
        "light position is not finite or beyond 1e10");

    GltfWriter c = gltfHostileInputGoodTriangle();
    c.doc["cameras"] =
        json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}});
    c.addNode({{"camera", 0}, {"translation", {0, -3e10, 0}}});
    EXPECT_CONTAINS(gltfHostileInputLoadError(c.write(dir, "camera")),
                    "camera position is not finite");
}
