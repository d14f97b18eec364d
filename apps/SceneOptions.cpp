#include "SceneOptions.h"

#include "core/Error.h"
#include "core/Suggest.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace pb::app {

void addSceneOptions(CLI::App& cmd, SceneArgs& a) {
    std::string names;
    for (const auto& n : scene::builtinSceneNames())
        names += (names.empty() ? "" : ", ") + n;
    cmd.add_option("--scene", a.scene,
                   "Built-in scene name (" + names + ") or path to a .gltf/.glb file")
        ->capture_default_str();
    cmd.add_option("--sun", a.sun,
                   "Override the sun: 'off' or DIRX,DIRY,DIRZ[,INTENSITY] (direction towards the "
                   "sun, intensity = irradiance on a surface facing it)");
    cmd.add_option("--sky", a.sky, "Override the constant sky radiance: R,G,B (linear)");
    cmd.add_option("--dynamic", a.dynamicNodes,
                   "Mark the glTF node NAME (and its mesh) dynamic: not baked, lit by the dynamic "
                   "GI path (repeatable)");
    cmd.add_flag("--allow-external-uris", a.allowExternalUris,
                 "Let a glTF's buffer and image URIs be absolute or leave its folder");
}

// A name that is neither a built-in scene nor a glTF path is most likely a typo of a built-in:
// say which (the loader's own message, in renderer/scene/, cannot guess).
void requireSceneName(const std::string& name) {
    const auto& builtins = scene::builtinSceneNames();
    if (std::find(builtins.begin(), builtins.end(), name) != builtins.end()) return;
    std::string ext = std::filesystem::path(name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".gltf" || ext == ".glb") return;
    std::string names;
    for (const auto& n : builtins)
        names += (names.empty() ? "" : ", ") + n;
    throw fileError(name, "not a built-in scene" + didYouMean(name, builtins) + " (" + names +
                              ") nor a .gltf/.glb file");
}

scene::Scene loadSceneWithOverrides(const SceneArgs& a) {
    requireSceneName(a.scene);
    scene::SceneOptions opts;
    opts.dynamicNodes = a.dynamicNodes;
    opts.allowExternalUris = a.allowExternalUris;
    scene::Scene s = scene::loadScene(a.scene, opts);
    if (!a.sun.empty()) scene::applySunOverride(s, a.sun);
    if (!a.sky.empty()) scene::applySkyOverride(s, a.sky);
    for (const auto& w : s.warnings)
        std::cerr << "warning: " << w << "\n";
    return s;
}

std::string sceneSummary(const scene::Scene& s) {
    size_t dynamic = 0;
    for (const auto& i : s.instances)
        dynamic += i.dynamic;
    char buf[512];
    const scene::Bounds b = s.worldBounds();
    std::string text = s.name + ": " + std::to_string(s.triangleCount()) + " triangles, " +
                       std::to_string(s.instances.size()) + " instances";
    if (dynamic > 0) text += " (" + std::to_string(dynamic) + " dynamic)";
    if (b.empty()) return text + ", no geometry";
    const glm::vec3 sz = b.size();
    std::snprintf(buf, sizeof buf,
                  ", bounds (%.4g,%.4g,%.4g)..(%.4g,%.4g,%.4g), size %.4g x %.4g x %.4g", b.min.x,
                  b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, sz.x, sz.y, sz.z);
    return text + buf;
}

scene::View chooseView(const scene::Scene& s, const std::string& viewName,
                       const std::string& cameraSpec) {
    if (!cameraSpec.empty()) return scene::parseCameraSpec(cameraSpec);
    if (viewName.empty()) return s.views.front();
    if (const scene::View* v = s.findView(viewName)) return *v;
    std::string names;
    std::vector<std::string> list;
    for (const auto& v : s.views) {
        names += (names.empty() ? "" : ", ") + v.name;
        list.push_back(v.name);
    }
    throw Error("--view '" + viewName + "': scene '" + s.name + "' has no such view" +
                didYouMean(viewName, list) + " (views: " + names + ")");
}

std::string cameraSpec(const scene::View& v) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", v.position.x, v.position.y,
                  v.position.z, v.target.x, v.target.y, v.target.z, v.fovYDegrees);
    return buf;
}

} // namespace pb::app
