#pragma once
// Scene selection and lighting overrides shared by every command that loads a scene.
#include "scene/SceneLoader.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace pb::app {

struct SceneArgs {
    std::string scene = "cornell";
    std::string sun;   // empty = scene default
    std::string sky;
    std::vector<std::string> dynamicNodes;
};

void addSceneOptions(CLI::App& cmd, SceneArgs& args);
// Loads the scene, applies the overrides and prints its warnings to stderr.
scene::Scene loadSceneWithOverrides(const SceneArgs& args);

} // namespace pb::app
