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
// Bytes of vertex and index data the scene may hold in all. A single accessor is bounded by
// its buffer, but many primitives may read the same accessor (or an all-zero accessor has no
// buffer at all): the budget keeps a small hostile file from asking for tens of GB. About 20 M
// vertices with normals, UVs and indices; the largest shared scene needs 10 MB.
constexpr std::size_t kMaxGeometryBytes = std::size_t(1) << 30;
// Instances (node x primitive): 10^5 nodes naming a mesh of 10^4 primitives fit in 2 MB of
// JSON and would be 10^9 instances.
constexpr std::size_t kMaxInstances = std::size_t(1) << 20;

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
    std::set<int> missingImages;            // files not found (warned about by the prepass)
    std::set<int> basisuOnlyTextures;       // KHR_texture_basisu without a PNG/JPEG fallback
    std::set<int> uvTransformWarned;        // materials warned about (GltfTextureTransform)
    std::map<int, std::vector<int>> meshes; // glTF mesh -> Scene::primitives
    std::size_t geometryBytes = 0;          // charged by reserveGeometry
    std::set<std::string> viewNames;        // names taken by Scene::views
    std::map<std::string, int> nextViewSuffix;

    [[noreturn]] void fail(const std::string& problem) const { throw fileError(path, problem); }
    void warn(const std::string& problem) { otherWarnings.push_back(path + ": " + problem); }

    // Charges `count` elements of `elementBytes` each against kMaxGeometryBytes before they
    // are allocated; fails naming `what` when the scene would need more.
    void reserveGeometry(std::size_t count, std::size_t elementBytes, const std::string& what) {
        const std::size_t limit = kMaxGeometryBytes - geometryBytes;
        if (count > limit / elementBytes)
            fail(what + ": the scene's vertex and index data would exceed " +
                 std::to_string(kMaxGeometryBytes >> 20) +
                 " MiB (a huge accessor, or one read by very many primitives)");
        geometryBytes += count * elementBytes;
    }

    // A view name not yet taken: `base`, else base_2, base_3, ... (uniqueViewName's rule) in
    // O(log n) per view, so a file with 10^5 cameras of one name cannot stall the load.
    std::string uniqueViewName(const std::string& base) {
        const std::string stem = base.empty() ? std::string("view") : base;
        std::string name = stem;
        if (viewNames.count(name)) {
            int& next = nextViewSuffix.try_emplace(stem, 2).first->second;
            do
                name = stem + "_" + std::to_string(next++);
            while (viewNames.count(name));
        }
        viewNames.insert(name);
        return name;
    }

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
