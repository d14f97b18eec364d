#pragma once
// State shared by the parts of the glTF loader (accessors, meshes, materials, nodes) while
// one file is converted. Internal to renderer/scene.
#include "core/Error.h"
#include "scene/Scene.h"

#include <map>
#include <set>
#include <string>
#include <tiny_gltf.h>
#include <vector>

namespace pb::scene::gltf {

// Anything above this is treated as a corrupt or hostile file rather than a big scene: the
// largest shared scene has 0.2 M vertices, and 2^28 floats of one attribute already need 3 GB.
constexpr std::size_t kMaxElements = std::size_t(1) << 28;

struct Context {
    Context(std::string p, const tinygltf::Model& m, Scene& s)
        : path(std::move(p)), model(m), scene(s) {}

    std::string path;
    const tinygltf::Model& model;
    Scene& scene;

    // Problems that are not worth failing the load for, counted so that each kind gives ONE
    // warning however often it occurs (a file can have thousands of line primitives).
    std::map<std::string, int> skippedPrimitives; // reason -> count
    std::set<int> skippedModes;
    int regeneratedNormals = 0;
    std::vector<std::string> otherWarnings;

    bool sunFromFile = false;               // a directional light became Scene::sun
    int defaultMaterial = -1;               // Scene::materials index, created on first use
    std::map<int, int> imageToTexture;      // glTF image -> Scene::textures
    std::map<int, std::vector<int>> meshes; // glTF mesh -> Scene::primitives

    [[noreturn]] void fail(const std::string& problem) const { throw fileError(path, problem); }
    void warn(const std::string& problem) { otherWarnings.push_back(path + ": " + problem); }

    // "mesh 'name'" or "mesh 3": how errors name things (names help, indices always work).
    std::string label(const char* kind, int index, const std::string& name) const {
        // Appended piece by piece: `"literal" + std::string` trips GCC 12's -Wrestrict.
        std::string out(kind);
        if (name.empty())
            out.append(" ").append(std::to_string(index));
        else
            out.append(" '").append(name).append("'");
        return out;
    }
    std::string meshLabel(int mesh) const {
        return label("mesh", mesh, model.meshes[size_t(mesh)].name);
    }
    std::string nodeLabel(int node) const {
        return label("node", node, model.nodes[size_t(node)].name);
    }
};

// obj[key], or nullptr when `obj` is not an object or lacks `key` (tinygltf's own Value::Get
// asserts on non-objects, and extension/extras content is whatever the file says).
inline const tinygltf::Value* member(const tinygltf::Value& obj, const char* key) {
    return obj.Has(key) ? &obj.Get(key) : nullptr;
}

} // namespace pb::scene::gltf
