// loadGltf: tinygltf parses the file, the Gltf* parts check and convert what it found.
#include "core/FileIO.h"
#include "scene/GltfContext.h"
#include "scene/GltfDecompress.h"
#include "scene/GltfInputChecks.h"
#include "scene/GltfMaterials.h"
#include "scene/GltfMeshes.h"
#include "scene/GltfNodes.h"
#include "scene/GltfPrepass.h"
#include "scene/SceneLoader.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace pb::scene {

using namespace gltf; // the checks tinygltf is wrapped in

namespace {

// tinygltf reports several problems as several lines; pb::Error messages are one line.
std::string oneLine(const std::string& text) {
    std::string out;
    bool pendingBreak = false;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            pendingBreak = true;
            continue;
        }
        if (pendingBreak && !out.empty()) out += "; ";
        pendingBreak = false;
        out += c;
    }
    return out;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

PreparedGltf parseWithTinygltf(const std::string& path, bool allowExternalUris,
                               tinygltf::Model& model, std::vector<std::string>& warnings) {
    const std::vector<unsigned char> bytes = readFileBytes(path); // "path: file not found" etc.
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw fileError(path, "larger than 4 GiB, which tinygltf cannot read");
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    const std::string baseDir = dir.string();

    checkRawGltf(path, bytes); // GLB structure, JSON nesting
    // Extensions, URIs, missing images: before tinygltf opens any buffer or image.
    PreparedGltf prepared = prepareGltf(path, bytes, baseDir, allowExternalUris);
    for (std::string& w : prepared.warnings)
        warnings.push_back(std::move(w));
    const std::vector<unsigned char>& input = prepared.bytes;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(regularFileCallbacks());
    ImageGuard imageGuard{&model};
    loader.SetImageLoader(&checkedImageLoader, &imageGuard);
    std::string err, warn;
    const bool binary = input.size() >= 4 && std::memcmp(input.data(), "glTF", 4) == 0;
    if (input.size() > std::numeric_limits<unsigned int>::max())
        throw fileError(path, "larger than 4 GiB, which tinygltf cannot read");
    const auto size = static_cast<unsigned int>(input.size());
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, input.data(), size, baseDir)
               : loader.LoadASCIIFromString(&model, &err, &warn,
                                            reinterpret_cast<const char*>(input.data()), size,
                                            baseDir);
    if (!ok) {
        if (err.empty()) err = warn.empty() ? "not a valid glTF file" : warn;
        // nlohmann's "[json.exception.parse_error.101] parse error at line ..." -> say what it is.
        if (err.rfind("[json.exception", 0) == 0)
            err = "malformed JSON: " + err.substr(err.find(']') + 2);
        throw fileError(path, oneLine(err));
    }
    // tinygltf also reports fixable oddities in `err` while still succeeding.
    for (const std::string& line : lines(err + "\n" + warn))
        warnings.push_back(path + ": " + line);
    return prepared;
}

void emitGroupedWarnings(gltf::Context& ctx) {
    for (const auto& [reason, count] : ctx.skippedPrimitives) {
        std::string text =
            ctx.path + ": skipped " + std::to_string(count) + " primitive(s): " + reason;
        if (reason == "mode is not TRIANGLES") {
            text += " (modes";
            for (int mode : ctx.skippedModes)
                text.append(" ").append(std::to_string(mode));
            text += ")";
        }
        ctx.scene.warnings.push_back(text);
    }
    if (ctx.regeneratedNormals > 0)
        ctx.scene.warnings.push_back(ctx.path + ": zero or non-finite normals in " +
                                     std::to_string(ctx.regeneratedNormals) +
                                     " primitive(s); smooth normals generated instead");
    if (!ctx.basisuOnlyTextures.empty())
        ctx.scene.warnings.push_back(
            ctx.path + ": " + std::to_string(ctx.basisuOnlyTextures.size()) +
            " texture(s) only in KHR_texture_basisu (KTX2, which probebench does not decode) "
            "without a PNG/JPEG fallback; their materials use their factors");
    for (std::string& w : ctx.otherWarnings)
        ctx.scene.warnings.push_back(std::move(w));
}

// Finite vertices can still end up absurdly far out (1e38, or a node scaled by 1e30); float
// maths on such bounds overflows, and nothing could be drawn there anyway. 1e10 m leaves room
// for geo-referenced scenes far from the origin.
void checkExtent(const std::string& path, const Bounds& b) {
    if (b.empty()) return;
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(b.min[a]) <= 1e10f) || !(std::abs(b.max[a]) <= 1e10f))
            throw fileError(path, "absurd world coordinates (beyond 1e10) after node transforms");
}

Scene loadGltfUnchecked(const std::string& path, const SceneOptions& options) {
    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    scene.sourcePath = path;

    tinygltf::Model model;
    const PreparedGltf prepared =
        parseWithTinygltf(path, options.allowExternalUris, model, scene.warnings);
    decompressMeshes(path, prepared.meshoptFallbacks, model);

    gltf::Context ctx{path, model, scene};
    ctx.missingImages = prepared.missingImages;
    // "default" comes first and is reserved before glTF cameras are named; its pose needs the
    // bounds, known once the nodes are walked.
    scene.views.push_back(View{"default"});
    ctx.viewNames.insert("default");
    gltf::convertMaterials(ctx);
    gltf::traverseNodes(ctx, options.dynamicNodes);
    if (scene.materials.empty()) gltf::defaultMaterial(ctx);
    emitGroupedWarnings(ctx);
    checkExtent(path, scene.worldBounds());
    deriveFromGeometry(scene);
    return scene;
}

} // namespace

Scene loadGltf(const std::string& path, const SceneOptions& options) {
    // Whatever tinygltf, its JSON parser or an allocation throws still becomes the one-line
    // "path: problem" error the command line prints.
    try {
        return loadGltfUnchecked(path, options);
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw fileError(path, "out of memory (absurd sizes in the file?)");
    } catch (const std::exception& e) {
        throw fileError(path, oneLine(e.what()));
    }
}

} // namespace pb::scene
