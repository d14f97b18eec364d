#pragma once
// Reading a probe file for a scene: every command that takes both checks that the file was
// baked for that scene (probes/bake/SceneMatch.h), with `--force` to use it anyway.
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <CLI/CLI.hpp>
#include <string>

namespace pb::app {

void addForceProbesFlag(CLI::App& cmd, bool& force);

// readProbeFileWithRanks, then a one-line error naming `path` if it was baked for another
// scene (unless `force`).
probes::ProbeSet readProbesForScene(const std::string& path, const scene::Scene& scene,
                                    bool force);

} // namespace pb::app
