#pragma once
// A look at a glTF file's JSON (nlohmann-json) before tinygltf reads any buffer or image:
// required extensions probebench cannot honour, URIs that leave the asset's folder and
// missing image files are found here, where tinygltf would instead fail with its own words
// ("Invalid 'byteLength'" for a meshopt GLB) or open whatever path the file names.
// Internal to renderer/scene.
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace pb::scene::gltf {

struct PreparedGltf {
    // What tinygltf reads: the file's own bytes, or the same file with its JSON rewritten
    // (a GLB keeps its BIN chunk untouched).
    std::vector<unsigned char> bytes;
    // EXT_meshopt_compression fallback buffers (never read: the compressed views are decoded
    // into them) -> their byteLength. tinygltf sees a one-byte stand-in.
    std::map<int, std::size_t> meshoptFallbacks;
    // Images whose file is missing (already warned about) or that are KTX2 (KHR_texture_basisu):
    // tinygltf sees a 1x1 stand-in, the materials use their factors.
    std::set<int> missingImages;
    std::vector<std::string> warnings; // "path: problem", one per ignored extension / image
};

// Throws pb::Error "path: problem" for a required extension probebench does not support and
// for a buffer or image URI that is absolute or climbs out of `baseDir` (unless
// `allowExternalUris`). JSON tinygltf would reject is passed through unchanged for it to
// describe.
PreparedGltf prepareGltf(const std::string& path, const std::vector<unsigned char>& bytes,
                         const std::string& baseDir, bool allowExternalUris);

} // namespace pb::scene::gltf
