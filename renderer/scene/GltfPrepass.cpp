#include "scene/GltfPrepass.h"

#include "core/Error.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace pb::scene {

// A file may require any of these: GltfDecompress decodes the two compressions,
// GltfMeshes reads quantized attributes, GltfMaterials the material and texture ones,
// GltfNodes the lights.
const std::vector<std::string>& supportedGltfExtensions() {
    static const std::vector<std::string> names = {
        "EXT_meshopt_compression",         "KHR_draco_mesh_compression",
        "KHR_lights_punctual",             "KHR_materials_emissive_strength",
        "KHR_mesh_quantization",           "KHR_texture_transform",
    };
    return names;
}

namespace gltf {

namespace {

using nlohmann::json;

// Used-only extensions that need no warning of their own: a KHR_texture_basisu texture
// keeps its PNG/JPEG `source` as the fallback (GltfMaterials warns once for textures that
// have none).
const char* const kUnderstoodOptional[] = {"KHR_texture_basisu"};

// 1x1 white PNG: what tinygltf decodes in place of a missing image file, so that it neither
// fails nor adds warnings of its own; the materials ignore it (PreparedGltf::missingImages).
const char* const kStandInPng =
    "data:image/png;base64,"
    "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAAC0lEQVR4nGP4DwQACfsD/fteaysAAAAASUVORK5CYII=";
// One zero byte: the stand-in for an EXT_meshopt_compression fallback buffer.
const char* const kStandInBuffer = "data:application/octet-stream;base64,AA==";

bool isSupported(const std::string& ext) {
    const auto& s = supportedGltfExtensions();
    return std::find(s.begin(), s.end(), ext) != s.end();
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::vector<std::string> stringArray(const json& doc, const char* key) {
    std::vector<std::string> out;
    auto it = doc.find(key);
    if (it == doc.end() || !it->is_array()) return out;
    for (const json& v : *it)
        if (v.is_string()) out.push_back(v.get<std::string>());
    return out;
}

void checkExtensions(const std::string& path, const json& doc, PreparedGltf& out) {
    const std::vector<std::string> required = stringArray(doc, "extensionsRequired");
    std::vector<std::string> unsupported;
    for (const std::string& ext : required)
        if (!isSupported(ext) &&
            std::find(unsupported.begin(), unsupported.end(), ext) == unsupported.end())
            unsupported.push_back(printable(ext));
    if (!unsupported.empty())
        throw fileError(path, std::string("requires glTF extension") +
                                  (unsupported.size() > 1 ? "s " : " ") + joined(unsupported) +
                                  ", which probebench does not support (supported: " +
                                  joined(supportedGltfExtensions()) + ")");
    std::set<std::string> warned;
    for (const std::string& ext : stringArray(doc, "extensionsUsed")) {
        if (isSupported(ext) || !warned.insert(ext).second) continue;
        bool understood = false;
        for (const char* u : kUnderstoodOptional)
            understood = understood || ext == u;
        if (!understood)
            out.warnings.push_back(path + ": uses glTF extension " + printable(ext) +
                                   ", which probebench ignores");
    }
}

bool isDataUri(const std::string& uri) {
    return uri.rfind("data:", 0) == 0;
}

// %XX escapes and '+' decoded, as tinygltf does before it opens the file.
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
            continue;
        }
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
            std::isxdigit((unsigned char)uri[i + 2])) {
            out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// Why `file` (a decoded URI) is not a path inside the asset's folder, or "". Lexical: a
// scheme ("file:", "http:", "C:"), a leading slash, or more ".." than folders before them.
std::string escapeProblem(const std::string& file) {
    if (file.empty()) return "";
    if (file[0] == '/' || file[0] == '\\') return "is an absolute path";
    const std::size_t colon = file.find(':');
    const std::size_t slash = file.find_first_of("/\\");
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        return "is not a relative path (it has a scheme or drive)";
    int depth = 0;
    std::size_t start = 0;
    while (start <= file.size()) {
        std::size_t end = file.find_first_of("/\\", start);
        if (end == std::string::npos) end = file.size();
        const std::string part = file.substr(start, end - start);
        if (part == "..") {
            if (--depth < 0) return "climbs out of the asset's folder";
        } else if (!part.empty() && part != ".") {
            ++depth;
        }
        start = end + 1;
    }
    return "";
}

// `file` as a URI again: tinygltf decodes %XX and '+'.
std::string encodedUri(const std::string& file) {
    std::string out;
    for (char c : file)
        out += c == '%' ? std::string("%25") : c == '+' ? std::string("%2B") : std::string(1, c);
    return out;
}

// Refuses `file` (a decoded URI) when it leaves the asset's folder, unless allowed; then
// returns the URI tinygltf should open, or "" to keep the file's own. tinygltf joins every
// URI to the folder, so an allowed absolute path (or "sub/../../x" through a folder that does
// not exist) is handed over as a normalised path relative to the folder.
std::string checkUri(const std::string& path, const std::string& what, const std::string& file,
                     const std::string& baseDir, bool allowExternal) {
    const std::string problem = escapeProblem(file);
    if (problem.empty()) return "";
    if (!allowExternal)
        throw fileError(path, what + " uri '" + printable(file) + "' " + problem +
                                  " (--allow-external-uris permits it)");
    namespace fs = std::filesystem;
    if (problem.find("scheme") != std::string::npos) return ""; // tinygltf reports it missing
    const fs::path dir = fs::absolute(baseDir).lexically_normal();
    const fs::path target = (file[0] == '/' ? fs::path(file) : dir / file).lexically_normal();
    const fs::path relative = target.lexically_relative(dir);
    return relative.empty() ? "" : encodedUri(relative.string());
}

bool hasMeshoptFallback(const json& buffer) {
    auto ext = buffer.find("extensions");
    if (ext == buffer.end() || !ext->is_object()) return false;
    auto m = ext->find("EXT_meshopt_compression");
    if (m == ext->end() || !m->is_object()) return false;
    auto f = m->find("fallback");
    return f != m->end() && f->is_boolean() && f->get<bool>();
}

// Returns true when the document was changed.
bool checkBuffers(const std::string& path, json& doc, const std::string& baseDir,
                  bool allowExternal, PreparedGltf& out) {
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return false;
    bool changed = false;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        json& b = (*buffers)[i];
        if (!b.is_object()) continue;
        const std::string what = "buffer " + std::to_string(i);
        if (hasMeshoptFallback(b)) { // decoded, never read: its URI need not even exist
            auto len = b.find("byteLength");
            if (len == b.end() || !len->is_number_unsigned())
                throw fileError(path, what + " (EXT_meshopt_compression fallback) has no byteLength");
            out.meshoptFallbacks[int(i)] = len->get<std::size_t>();
            b = json{{"byteLength", 1}, {"uri", kStandInBuffer}};
            changed = true;
            continue;
        }
        auto uri = b.find("uri");
        if (uri == b.end() || !uri->is_string() || isDataUri(uri->get<std::string>())) continue;
        // A missing buffer stays tinygltf's error ("File not found").
        const std::string rewritten = checkUri(
            path, what, percentDecoded(uri->get<std::string>()), baseDir, allowExternal);
        if (!rewritten.empty()) {
            *uri = rewritten;
            changed = true;
        }
    }
    return changed;
}

// A KTX2 picture (KHR_texture_basisu): probebench decodes PNG and JPEG only.
bool isKtx2(const json& img) {
    auto mime = img.find("mimeType");
    if (mime != img.end() && mime->is_string() && mime->get<std::string>() == "image/ktx2")
        return true;
    auto uri = img.find("uri");
    if (uri == img.end() || !uri->is_string()) return false;
    const std::string u = uri->get<std::string>();
    return u.size() > 5 && u.compare(u.size() - 5, 5, ".ktx2") == 0;
}

bool checkImages(const std::string& path, json& doc, const std::string& baseDir,
                 bool allowExternalUris, PreparedGltf& out) {
    auto images = doc.find("images");
    if (images == doc.end() || !images->is_array()) return false;
    bool changed = false;
    for (std::size_t i = 0; i < images->size(); ++i) {
        json& img = (*images)[i];
        if (!img.is_object()) continue;
        if (isKtx2(img)) { // only KHR_texture_basisu names these; GltfMaterials warns once
            img = json{{"uri", kStandInPng}};
            out.missingImages.insert(int(i));
            changed = true;
            continue;
        }
        auto uri = img.find("uri");
        if (uri == img.end() || !uri->is_string() || isDataUri(uri->get<std::string>())) continue;
        const std::string what = "image " + std::to_string(i);
        const std::string rewritten = checkUri(path, what, percentDecoded(uri->get<std::string>()),
                                               baseDir, allowExternalUris);
        if (!rewritten.empty()) {
            *uri = rewritten;
            changed = true;
        }
        std::error_code ec;
        const std::filesystem::path full =
            std::filesystem::path(baseDir) / percentDecoded(uri->get<std::string>());
        if (!std::filesystem::is_regular_file(full, ec)) {
            out.warnings.push_back(path + ": " + what + " file '" + printable(full.string()) +
                                   "' not found; its materials use their factors");
            out.missingImages.insert(int(i));
            *uri = kStandInPng;
            img.erase("mimeType");
            changed = true;
        }
    }
    return changed;
}

// tinygltf refuses an indices accessor without a bufferView, which is what a Draco primitive
// has: the indices are dropped here, GltfDraco sets new ones from the decoded mesh.
bool dropDracoIndices(json& doc) {
    auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array()) return false;
    bool changed = false;
    for (json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (json& prim : mesh["primitives"]) {
            if (!prim.is_object() || !prim.contains("extensions") ||
                !prim["extensions"].is_object() ||
                !prim["extensions"].contains("KHR_draco_mesh_compression"))
                continue;
            changed = prim.erase("indices") > 0 || changed;
        }
    }
    return changed;
}

std::uint32_t le32(const unsigned char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

void putLe32(std::vector<unsigned char>& out, std::uint32_t v) {
    unsigned char b[4];
    std::memcpy(b, &v, 4);
    out.insert(out.end(), b, b + 4);
}

// The GLB with its JSON chunk replaced by `text`; the chunks after it are copied as they are.
std::vector<unsigned char> rebuiltGlb(const std::vector<unsigned char>& glb, std::string text,
                                      std::size_t jsonEnd) {
    while (text.size() % 4 != 0)
        text += ' ';
    std::vector<unsigned char> out(glb.begin(), glb.begin() + 12);
    out.resize(8); // magic, version; the length follows once known
    const std::size_t total = 12 + 8 + text.size() + (glb.size() - jsonEnd);
    if (total > 0xffffffffu) throw std::length_error("GLB larger than 4 GiB");
    putLe32(out, std::uint32_t(total));
    putLe32(out, std::uint32_t(text.size()));
    putLe32(out, 0x4E4F534Au); // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), glb.begin() + std::ptrdiff_t(jsonEnd), glb.end());
    return out;
}

} // namespace

PreparedGltf prepareGltf(const std::string& path, const std::vector<unsigned char>& bytes,
                         const std::string& baseDir, bool allowExternalUris) {
    PreparedGltf out;
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    std::size_t jsonBegin = 0, jsonEnd = bytes.size();
    if (binary) {
        // checkRawGltf has bounded the JSON chunk; a GLB too short for one is tinygltf's to
        // describe.
        if (bytes.size() < 20) {
            out.bytes = bytes;
            return out;
        }
        jsonBegin = 20;
        jsonEnd = 20 + le32(bytes.data() + 12);
    }
    json doc = json::parse(bytes.begin() + std::ptrdiff_t(jsonBegin),
                           bytes.begin() + std::ptrdiff_t(jsonEnd), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) {
        out.bytes = bytes;
        return out;
    }
    checkExtensions(path, doc, out);
    bool changed = checkBuffers(path, doc, baseDir, allowExternalUris, out);
    changed = checkImages(path, doc, baseDir, allowExternalUris, out) || changed;
    changed = dropDracoIndices(doc) || changed;
    if (!changed) {
        out.bytes = bytes;
        return out;
    }
    const std::string text = doc.dump();
    if (binary)
        out.bytes = rebuiltGlb(bytes, text, jsonEnd);
    else
        out.bytes.assign(text.begin(), text.end());
    return out;
}

} // namespace gltf
} // namespace pb::scene
