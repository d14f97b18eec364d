#include "scene/SceneLoader.h"

#include "core/Error.h"
#include "scene/BuiltinScenes.h"
#include "scene/DefaultView.h"
#include "scene/RayGrid.h"
#include "scene/SkyVisibility.h"

#include <algorithm>
#include <cctype>

namespace pb::scene {

namespace {

std::string namesList() {
    std::string list;
    for (const std::string& n : builtinSceneNames())
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

bool hasGltfExtension(const std::string& path) {
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    auto endsWith = [&](const std::string& ext) {
        return lower.size() >= ext.size() &&
               lower.compare(lower.size() - ext.size(), ext.size(), ext) == 0;
    };
    return endsWith(".gltf") || endsWith(".glb");
}

} // namespace

const std::vector<std::string>& builtinSceneNames() {
    static const std::vector<std::string> names = {"cornell", "rooms", "courtyard", "empty",
                                                   "rooms_dynamic", "thin_wall"};
    return names;
}

bool isBuiltinScene(const std::string& name) {
    const auto& names = builtinSceneNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeBuiltinScene(const std::string& name) {
    Scene s;
    if (name == "cornell")
        s = makeCornellScene();
    else if (name == "rooms")
        s = makeRoomsScene();
    else if (name == "courtyard")
        s = makeCourtyardScene();
    else if (name == "rooms_dynamic")
        s = makeRoomsDynamicScene();
    else if (name == "thin_wall")
        s = makeThinWallScene();
    else if (name == "empty")
        s.name = "empty"; // no geometry; sun and sky keep their defaults (furnace tests set them)
    else
        throw Error("unknown built-in scene '" + name + "' (built-in scenes: " + namesList() + ")");
    if (s.materials.empty()) { // Scene promises at least one material
        s.materials.push_back(Material{});
        s.materials.back().name = "default";
    }
    s.views.insert(s.views.begin(), View{});
    deriveFromGeometry(s);
    return s;
}

void deriveFromGeometry(Scene& scene) {
    const RayGrid grid(scene);
    scene.views.front() = makeDefaultView(scene, grid);
    scene.sky.visibility = meanSkyVisibility(grid);
}

Scene loadScene(const std::string& nameOrPath, const SceneOptions& options) {
    if (isBuiltinScene(nameOrPath)) {
        Scene s = makeBuiltinScene(nameOrPath);
        // Built-in objects are named like glTF nodes (e.g. cornell's "tall_box").
        for (const std::string& node : options.dynamicNodes) {
            bool found = false;
            for (Instance& inst : s.instances)
                if (inst.nodeName == node) inst.dynamic = found = true;
            if (!found)
                throw Error("--dynamic: no node named '" + node + "' in built-in scene '" +
                            nameOrPath + "'");
        }
        // Dynamic objects neither block a view nor the sky.
        if (!options.dynamicNodes.empty()) deriveFromGeometry(s);
        return s;
    }
    if (!hasGltfExtension(nameOrPath))
        throw fileError(nameOrPath,
                        "not a built-in scene (" + namesList() + ") nor a .gltf/.glb file");
    return loadGltf(nameOrPath, options);
}

} // namespace pb::scene
