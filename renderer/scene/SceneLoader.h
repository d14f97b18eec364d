#pragma once
// Entry points that turn a `--scene` argument into a Scene, and the command-line overrides
// that apply to any scene. Errors throw pb::Error naming the file and the problem.
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace pb::scene {

struct SceneOptions {
    std::vector<std::string> dynamicNodes; // --dynamic NODE_NAME (repeatable)
    // --allow-external-uris: buffer and image URIs may be absolute or leave the glTF's folder.
    bool allowExternalUris = false;
};

// The glTF extensions loadGltf honours (a file may require any of them), sorted.
const std::vector<std::string>& supportedGltfExtensions();

// `nameOrPath` is a built-in scene name (see builtinSceneNames()) or a path to .gltf/.glb.
Scene loadScene(const std::string& nameOrPath, const SceneOptions& options = {});

// glTF 2.0 through tinygltf: node hierarchy, meshes, materials, textures, KHR_lights_punctual,
// cameras as views, node extras {"dynamic": true}. Non-triangle primitives are skipped with one
// warning in Scene::warnings.
Scene loadGltf(const std::string& path, const SceneOptions& options = {});

// Built-in procedural scenes: "cornell", "rooms", "courtyard" (and "empty": no geometry, for
// furnace tests). Throws pb::Error listing the valid names for an unknown one.
Scene makeBuiltinScene(const std::string& name);

// What loading derives from the static geometry, from one CPU ray grid (RayGrid.h): the first
// view becomes the default view (DefaultView.h) and the sky's share is measured
// (SkyVisibility.h). The loaders call it once they know which instances are dynamic.
void deriveFromGeometry(Scene& scene);
const std::vector<std::string>& builtinSceneNames();
bool isBuiltinScene(const std::string& name);

// --sun off|DIRX,DIRY,DIRZ[,INTENSITY]  (direction points towards the sun)
void applySunOverride(Scene& scene, const std::string& spec);
// --sky R,G,B  (constant sky radiance)
void applySkyOverride(Scene& scene, const std::string& spec);

// --camera px,py,pz,tx,ty,tz[,fovdeg]
View parseCameraSpec(const std::string& spec);

} // namespace pb::scene
