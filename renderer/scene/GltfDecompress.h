#pragma once
// Compressed geometry decoded into plain glTF data before the loader converts the model, so
// accessors, meshes and the rest never know a file was compressed. Internal to renderer/scene.
#include <cstddef>
#include <map>
#include <string>
#include <tiny_gltf.h>

namespace pb::scene::gltf {

// EXT_meshopt_compression bufferViews (libmeshoptimizer) are decoded into the bytes their
// bufferView names; `fallbacks` (buffer -> byteLength, PreparedGltf::meshoptFallbacks) are
// sized first. Throws pb::Error "path: problem" for data the decoder rejects.
void decodeMeshopt(const std::string& path, const std::map<int, std::size_t>& fallbacks,
                   tinygltf::Model& model);

// KHR_draco_mesh_compression primitives (libdraco) get new float / uint32 accessors in a new
// buffer in place of the ones the extension points at.
void decodeDraco(const std::string& path, tinygltf::Model& model);

inline void decompressMeshes(const std::string& path, const std::map<int, std::size_t>& fallbacks,
                             tinygltf::Model& model) {
    decodeMeshopt(path, fallbacks, model);
    decodeDraco(path, model);
}

} // namespace pb::scene::gltf
