// EXT_meshopt_compression: each compressed bufferView is decoded with libmeshoptimizer into
// the bytes the bufferView itself names (usually in a fallback buffer that was never read).
#include "scene/GltfContext.h"
#include "scene/GltfDecompress.h"

#include <cstring>
#include <meshoptimizer.h>

namespace pb::scene::gltf {

namespace {

struct MeshoptView {
    std::size_t buffer = 0, byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    std::string mode, filter = "NONE";
};

// A number member, or `fallback` when absent or not a number.
double numberOr(const tinygltf::Value& obj, const char* key, double fallback) {
    const tinygltf::Value* v = member(obj, key);
    return v && v->IsNumber() ? v->GetNumberAsDouble() : fallback;
}

std::size_t size(const std::string& path, const std::string& what, const tinygltf::Value& ext,
                 const char* key, bool required) {
    const double v = numberOr(ext, key, required ? -1.0 : 0.0);
    if (!(v >= 0.0) || v > double(std::size_t(1) << 40) || v != double(std::size_t(v)))
        throw fileError(path, what + ": EXT_meshopt_compression " + key +
                                  (required ? " missing or not" : " is not") +
                                  " a non-negative integer");
    return std::size_t(v);
}

std::string text(const tinygltf::Value& ext, const char* key) {
    const tinygltf::Value* v = member(ext, key);
    return v && v->IsString() ? v->Get<std::string>() : "";
}

MeshoptView parse(const std::string& path, const std::string& what, const tinygltf::Value& ext) {
    if (!ext.IsObject()) throw fileError(path, what + ": EXT_meshopt_compression is not an object");
    MeshoptView m;
    m.buffer = size(path, what, ext, "buffer", true);
    m.byteOffset = size(path, what, ext, "byteOffset", false);
    m.byteLength = size(path, what, ext, "byteLength", true);
    m.byteStride = size(path, what, ext, "byteStride", true);
    m.count = size(path, what, ext, "count", true);
    m.mode = text(ext, "mode");
    if (const std::string f = text(ext, "filter"); !f.empty()) m.filter = f;
    return m;
}

// Why `m` cannot be decoded as the extension describes, or "".
std::string shapeProblem(const MeshoptView& m) {
    if (m.count > kMaxElements) return "absurd count " + std::to_string(m.count);
    if (m.mode == "ATTRIBUTES") {
        if (m.byteStride == 0 || m.byteStride % 4 != 0 || m.byteStride > 256)
            return "ATTRIBUTES byteStride must be a multiple of 4 up to 256";
    } else if (m.mode == "TRIANGLES" || m.mode == "INDICES") {
        if (m.byteStride != 2 && m.byteStride != 4) return m.mode + " byteStride must be 2 or 4";
        if (m.mode == "TRIANGLES" && m.count % 3 != 0)
            return "TRIANGLES count is not a multiple of 3";
    } else {
        return "unknown mode '" + printable(m.mode) + "'";
    }
    if (m.filter == "NONE") return "";
    if (m.mode != "ATTRIBUTES") return "filter " + m.filter + " on " + m.mode + " data";
    if (m.filter == "OCTAHEDRAL" && m.byteStride != 4 && m.byteStride != 8)
        return "OCTAHEDRAL byteStride must be 4 or 8";
    if (m.filter == "QUATERNION" && m.byteStride != 8) return "QUATERNION byteStride must be 8";
    if (m.filter != "OCTAHEDRAL" && m.filter != "QUATERNION" && m.filter != "EXPONENTIAL")
        return "unknown filter '" + printable(m.filter) + "'";
    return "";
}

void decodeView(const std::string& path, int index, const tinygltf::Value& ext,
                tinygltf::Model& model) {
    const std::string what = "bufferView " + std::to_string(index);
    const MeshoptView m = parse(path, what, ext);
    if (const std::string p = shapeProblem(m); !p.empty())
        throw fileError(path, what + ": EXT_meshopt_compression " + p);
    if (m.buffer >= model.buffers.size())
        throw fileError(path, what + ": EXT_meshopt_compression names missing buffer " +
                                  std::to_string(m.buffer));
    const std::vector<unsigned char>& src = model.buffers[m.buffer].data;
    if (m.byteOffset > src.size() || m.byteLength > src.size() - m.byteOffset)
        throw fileError(path, what + ": EXT_meshopt_compression data reaches past the end of buffer " +
                                  std::to_string(m.buffer));
    const tinygltf::BufferView& bv = model.bufferViews[std::size_t(index)];
    const std::size_t bytes = m.count * m.byteStride;
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size() || bytes > bv.byteLength)
        throw fileError(path, what + ": EXT_meshopt_compression decodes to " +
                                  std::to_string(bytes) + " bytes, more than the bufferView holds");
    std::vector<unsigned char>& dst = model.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteOffset > dst.size() || bytes > dst.size() - bv.byteOffset)
        throw fileError(path, what + " reaches past the end of buffer " +
                                  std::to_string(bv.buffer));

    std::vector<unsigned char> out(bytes);
    const unsigned char* in = src.data() + m.byteOffset;
    int rc = 0;
    if (m.mode == "ATTRIBUTES")
        rc = meshopt_decodeVertexBuffer(out.data(), m.count, m.byteStride, in, m.byteLength);
    else if (m.mode == "TRIANGLES")
        rc = meshopt_decodeIndexBuffer(out.data(), m.count, m.byteStride, in, m.byteLength);
    else
        rc = meshopt_decodeIndexSequence(out.data(), m.count, m.byteStride, in, m.byteLength);
    if (rc != 0)
        throw fileError(path, what + ": EXT_meshopt_compression data is corrupt (" + m.mode +
                                  " decoder error " + std::to_string(rc) + ")");
    if (m.filter == "OCTAHEDRAL")
        meshopt_decodeFilterOct(out.data(), m.count, m.byteStride);
    else if (m.filter == "QUATERNION")
        meshopt_decodeFilterQuat(out.data(), m.count, m.byteStride);
    else if (m.filter == "EXPONENTIAL")
        meshopt_decodeFilterExp(out.data(), m.count, m.byteStride);
    if (bytes > 0) std::memcpy(dst.data() + bv.byteOffset, out.data(), bytes);
}

} // namespace

void decodeMeshopt(const std::string& path, const std::map<int, std::size_t>& fallbacks,
                   tinygltf::Model& model) {
    std::size_t total = 0;
    for (const auto& [buffer, length] : fallbacks) {
        // Zero-filled until decoded; a hostile byteLength must not allocate terabytes.
        if (length > kMaxGeometryBytes - total)
            throw fileError(path, "EXT_meshopt_compression fallback buffers declare more than " +
                                      std::to_string(kMaxGeometryBytes >> 20) + " MiB");
        total += length;
        model.buffers[std::size_t(buffer)].data.assign(length, 0);
    }
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const auto& exts = model.bufferViews[i].extensions;
        if (auto it = exts.find("EXT_meshopt_compression"); it != exts.end())
            decodeView(path, int(i), it->second, model);
    }
}

} // namespace pb::scene::gltf
