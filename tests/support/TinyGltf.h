#pragma once
// Writes small glTF files for tests: one triangle (or a quad), optionally broken on purpose.
#include <filesystem>
#include <string>

namespace pb::test {

struct TinyGltfOptions {
    int declaredBinBytes = -1;    // byteLength written in the JSON (-1 = the real size)
    int truncateBinTo = -1;       // bytes actually written to the .bin (-1 = all)
    unsigned badIndex = 0;        // if non-zero, the third index is replaced by this value
};

// Writes dir/name.gltf + dir/name.bin (a unit quad in the XZ plane facing +Y, two triangles,
// uint16 indices) and returns the .gltf path.
std::filesystem::path writeTinyGltf(const std::filesystem::path& dir, const std::string& name,
                                    const TinyGltfOptions& options = {});

} // namespace pb::test
