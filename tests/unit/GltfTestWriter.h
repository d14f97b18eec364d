#pragma once
// Writes small glTF files at test run time, so bad-input cases are generated from a good
// file plus one edit instead of committed as binaries.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pb::test {

class GltfWriter {
public:
    using json = nlohmann::json;
    json doc;
    std::vector<std::uint8_t> bin;

    GltfWriter() {
        doc = {{"asset", {{"version", "2.0"}}},
               {"scene", 0},
               {"scenes", json::array({json{{"nodes", json::array()}}})},
               {"nodes", json::array()},
               {"meshes", json::array()},
               {"accessors", json::array()},
               {"bufferViews", json::array()},
               {"buffers", json::array()}};
    }

    // Appends raw bytes (4-byte aligned) as a new bufferView; returns its index.
    int addBufferView(const void* data, std::size_t bytes, std::size_t stride = 0) {
        while (bin.size() % 4)
            bin.push_back(0);
        json bv = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride) bv["byteStride"] = stride;
        const auto* p = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), p, p + bytes);
        doc["bufferViews"].push_back(bv);
        return int(doc["bufferViews"].size()) - 1;
    }

    int addAccessor(int bufferView, int componentType, std::size_t count, const std::string& type,
                    std::size_t byteOffset = 0) {
        json a = {{"bufferView", bufferView},
                  {"componentType", componentType},
                  {"count", count},
                  {"type", type}};
        if (byteOffset) a["byteOffset"] = byteOffset;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size()) - 1;
    }

    int addVec3(const std::vector<glm::vec3>& v) {
        return addAccessor(addBufferView(v.data(), v.size() * 12), 5126, v.size(), "VEC3");
    }
    int addVec2(const std::vector<glm::vec2>& v) {
        return addAccessor(addBufferView(v.data(), v.size() * 8), 5126, v.size(), "VEC2");
    }
    // componentType 5121 (u8), 5123 (u16) or 5125 (u32).
    int addIndices(const std::vector<std::uint32_t>& idx, int componentType = 5125) {
        std::vector<std::uint8_t> bytes;
        const int size = componentType == 5121 ? 1 : componentType == 5123 ? 2 : 4;
        for (std::uint32_t i : idx) {
            std::uint8_t b[4];
            std::memcpy(b, &i, 4); // little endian: the low bytes come first
            bytes.insert(bytes.end(), b, b + size);
        }
        return addAccessor(addBufferView(bytes.data(), bytes.size()), componentType, idx.size(),
                           "SCALAR");
    }

    // One triangle-list primitive; returns the mesh index.
    int addMesh(const json& primitive, const std::string& name = "") {
        json mesh = {{"primitives", json::array({primitive})}};
        if (!name.empty()) mesh["name"] = name;
        doc["meshes"].push_back(mesh);
        return int(doc["meshes"].size()) - 1;
    }
    int addTriangleMesh(const std::vector<glm::vec3>& positions,
                        const std::vector<std::uint32_t>& indices, const std::string& name = "") {
        json prim = {{"attributes", {{"POSITION", addVec3(positions)}}}};
        if (!indices.empty()) prim["indices"] = addIndices(indices);
        return addMesh(prim, name);
    }

    int addNode(const json& node, bool root = true) {
        doc["nodes"].push_back(node);
        const int index = int(doc["nodes"].size()) - 1;
        if (root) doc["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    // Writes `dir/name.gltf` + `dir/name.bin`, or `dir/name.glb`; returns the path.
    std::string write(const std::filesystem::path& dir, const std::string& name, bool glb = false) {
        json d = doc;
        while (bin.size() % 4)
            bin.push_back(0);
        d["buffers"] = json::array({json{{"byteLength", bin.size()}}});
        if (glb) {
            std::string text = d.dump();
            while (text.size() % 4)
                text += ' ';
            std::vector<std::uint8_t> out;
            auto u32 = [&](std::uint32_t v) {
                const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
                out.insert(out.end(), p, p + 4);
            };
            u32(0x46546C67); // "glTF"
            u32(2);
            u32(std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
            u32(std::uint32_t(text.size()));
            u32(0x4E4F534A); // JSON
            out.insert(out.end(), text.begin(), text.end());
            u32(std::uint32_t(bin.size()));
            u32(0x004E4942); // BIN
            out.insert(out.end(), bin.begin(), bin.end());
            const auto path = dir / (name + ".glb");
            writeBytes(path, out.data(), out.size());
            return path.string();
        }
        d["buffers"][0]["uri"] = name + ".bin";
        writeBytes(dir / (name + ".bin"), bin.data(), bin.size());
        const std::string text = d.dump(1);
        const auto path = dir / (name + ".gltf");
        writeBytes(path, text.data(), text.size());
        return path.string();
    }

    static void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size) {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(static_cast<const char*>(data), std::streamsize(size));
    }
};

// A unit right triangle in the XY plane facing +Z (counter-clockwise seen from +Z).
inline std::vector<glm::vec3> triangleXY() {
    return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

} // namespace pb::test
