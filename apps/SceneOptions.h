#pragma once
// Scene selection and lighting overrides shared by every command that loads a scene.
#include "scene/SceneLoader.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace pb::app {

struct SceneArgs {
    std::string scene = "cornell";
    std::string sun; // empty = scene default
    std::string sky;
    std::vector<std::string> dynamicNodes;
    bool allowExternalUris = false;
};

void addSceneOptions(CLI::App& cmd, SceneArgs& args);
// Loads the scene, applies the overrides and prints its warnings to stderr.
scene::Scene loadSceneWithOverrides(const SceneArgs& args);
// One line for people: "rooms: 192 triangles, 16 instances (2 dynamic), bounds
// (-3,0,-2)..(3,2.5,2), size 6 x 2.5 x 4" (scene units; glTF says metres).
std::string sceneSummary(const scene::Scene& s);
// The camera of --camera SPEC if given, else the view named by --view, else the scene's first
// view. Throws pb::Error listing the scene's views for an unknown name.
scene::View chooseView(const scene::Scene& s, const std::string& viewName,
                       const std::string& cameraSpec);

// The --camera form of a view ("px,py,pz,tx,ty,tz,fov", 6 significant digits), so a chosen or
// found camera can be pasted into render, bench or views.
std::string cameraSpec(const scene::View& v);

} // namespace pb::app
