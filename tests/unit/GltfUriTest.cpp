// Buffer and image URIs stay inside the glTF's folder: absolute ones and ones that climb out
// with ".." are refused (one error line) unless SceneOptions::allowExternalUris; data URIs and
// relative paths inside the folder work; a missing buffer stays an error.
#include "core/Error.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <filesystem>
#include <gtest/gtest.h>

using namespace pb::scene;
using pb::test::GltfWriter;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Writes the triangle file `dir/name.gltf` whose buffer URI is `uri` (its bytes are written
// to `binPath` when given) and returns the .gltf path.
std::string triangleWithBufferUri(const fs::path& dir, const std::string& name,
                                  const std::string& uri, const fs::path& binPath = {}) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"mesh", 0}});
    const std::string path = w.write(dir, name);
    json d = json::parse(std::ifstream(path));
    d["buffers"][0]["uri"] = uri;
    const std::string text = d.dump();
    GltfWriter::writeBytes(path, text.data(), text.size());
    if (!binPath.empty()) {
        fs::create_directories(binPath.parent_path());
        fs::copy_file(dir / (name + ".bin"), binPath, fs::copy_options::overwrite_existing);
    }
    return path;
}

std::string gltfUriLoadError(const std::string& path, const SceneOptions& options = {}) {
    try {
        loadGltf(path, options);
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "";
}

SceneOptions allowExternal() {
    SceneOptions o;
    o.allowExternalUris = true;
    return o;
}

} // namespace

TEST(GltfUri, ClimbingOutOfTheFolderIsRefusedUnlessAllowed) {
    const fs::path dir = pb::test::outputDir();
    const fs::path asset = dir / "asset";
    fs::create_directories(asset);
    const std::string path =
        triangleWithBufferUri(asset, "up", "sub/../../outside.bin", dir / "outside.bin");
    const std::string msg = gltfUriLoadError(path);
    EXPECT_EQ(msg, path + ": buffer 0 uri 'sub/../../outside.bin' climbs out of the asset's "
                          "folder (--allow-external-uris permits it)");
    EXPECT_EQ(loadGltf(path, allowExternal()).triangleCount(), 1u);
}

TEST(GltfUri, TheIssuesPasswdUriIsNeverOpened) {
    const fs::path dir = pb::test::outputDir();
    const std::string path = triangleWithBufferUri(dir, "passwd", "../../../../etc/passwd");
    EXPECT_NE(gltfUriLoadError(path).find("climbs out of the asset's folder"), std::string::npos);
    // Percent-escaped dots are the same path to tinygltf.
    const std::string escaped = triangleWithBufferUri(dir, "pct", "%2e%2e/%2E%2E/etc/passwd");
    EXPECT_NE(gltfUriLoadError(escaped).find("climbs out"), std::string::npos)
        << gltfUriLoadError(escaped);
}

TEST(GltfUri, AbsoluteAndSchemeUrisAreRefused) {
    const fs::path dir = pb::test::outputDir();
    const fs::path bin = dir / "abs" / "tri.bin";
    const std::string absolute = triangleWithBufferUri(dir, "absolute", bin.string(), bin);
    EXPECT_NE(gltfUriLoadError(absolute).find("is an absolute path"), std::string::npos)
        << gltfUriLoadError(absolute);
    EXPECT_EQ(loadGltf(absolute, allowExternal()).triangleCount(), 1u);
    const std::string scheme = triangleWithBufferUri(dir, "scheme", "file:///etc/passwd");
    EXPECT_NE(gltfUriLoadError(scheme).find("not a relative path"), std::string::npos);
}

TEST(GltfUri, ImageUrisAreConfinedToo) {
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"mesh", 0}});
    w.doc["images"] = json::array({{{"uri", "../secret.png"}}});
    w.doc["textures"] = json::array({{{"source", 0}}});
    w.doc["materials"] =
        json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    const std::string path = w.write(pb::test::outputDir(), "img");
    EXPECT_NE(gltfUriLoadError(path).find("image 0 uri '../secret.png' climbs out"),
              std::string::npos)
        << gltfUriLoadError(path);
}

TEST(GltfUri, RelativePathsInsideAndDataUrisWork) {
    const fs::path dir = pb::test::outputDir();
    const std::string inside =
        triangleWithBufferUri(dir, "inside", "./data/../data/tri.bin", dir / "data" / "tri.bin");
    EXPECT_EQ(loadGltf(inside).triangleCount(), 1u);
    const std::string spaced =
        triangleWithBufferUri(dir, "spaced", "my%20data/tri.bin", dir / "my data" / "tri.bin");
    EXPECT_EQ(loadGltf(spaced).triangleCount(), 1u);
    // A data URI buffer: the triangle's 36 position bytes and 12 index bytes, base64.
    GltfWriter w;
    w.addTriangleMesh(pb::test::triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"mesh", 0}});
    const std::string path = w.write(dir, "datauri");
    json d = json::parse(std::ifstream(path));
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string enc;
    for (size_t i = 0; i < w.bin.size(); i += 3) {
        const unsigned v = unsigned(w.bin[i]) << 16 |
                           (i + 1 < w.bin.size() ? unsigned(w.bin[i + 1]) << 8 : 0u) |
                           (i + 2 < w.bin.size() ? unsigned(w.bin[i + 2]) : 0u);
        enc += b64[v >> 18 & 63];
        enc += b64[v >> 12 & 63];
        enc += i + 1 < w.bin.size() ? b64[v >> 6 & 63] : '=';
        enc += i + 2 < w.bin.size() ? b64[v & 63] : '=';
    }
    d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + enc;
    const std::string text = d.dump();
    GltfWriter::writeBytes(path, text.data(), text.size());
    fs::remove(dir / "datauri.bin");
    EXPECT_EQ(loadGltf(path).triangleCount(), 1u);
}

TEST(GltfUri, MissingBufferStaysAnError) {
    const fs::path dir = pb::test::outputDir();
    const std::string path = triangleWithBufferUri(dir, "nobuf", "gone.bin");
    const std::string msg = gltfUriLoadError(path);
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("gone.bin"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}
