#include "support/TinyGltf.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace pb::test {

std::filesystem::path writeTinyGltf(const std::filesystem::path& dir, const std::string& name,
                                    const TinyGltfOptions& o) {
    const float pos[] = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    std::vector<uint16_t> idx = {0, 2, 1, 0, 3, 2};
    if (o.badIndex) idx[2] = uint16_t(o.badIndex);
    std::vector<char> bin(sizeof pos + idx.size() * 2);
    std::memcpy(bin.data(), pos, sizeof pos);
    std::memcpy(bin.data() + sizeof pos, idx.data(), idx.size() * 2);
    int realBytes = int(bin.size());
    int declared = o.declaredBinBytes >= 0 ? o.declaredBinBytes : realBytes;
    std::ofstream(dir / (name + ".bin"), std::ios::binary)
        .write(bin.data(), o.truncateBinTo >= 0 ? o.truncateBinTo : realBytes);
    std::string json = R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "name": "quad"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"uri": ")" + name + R"(.bin", "byteLength": )" + std::to_string(declared) + R"(}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 48},
    {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
     "min": [-1, 0, -1], "max": [1, 0, 1]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
    auto path = dir / (name + ".gltf");
    std::ofstream(path) << json;
    return path;
}

} // namespace pb::test
