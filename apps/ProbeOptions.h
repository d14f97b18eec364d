#pragma once
// Reading a probe file for a scene: every command that takes both checks that the file was
// baked for that scene (probes/bake/SceneMatch.h), with `--force` to use it anyway.
#include "probes/ProbeSet.h"
#include "profile/Profile.h"
#include "scene/Scene.h"

#include <CLI/CLI.hpp>
#include <string>

namespace pb::app {

void addForceProbesFlag(CLI::App& cmd, bool& force);

// readProbeFileWithRanks, then a one-line error naming `path` if it was baked for another
// scene (unless `force`).
probes::ProbeSet readProbesForScene(const std::string& path, const scene::Scene& scene,
                                    bool force);

// A one-line error naming `path` when the profile's gi.technique needs data the file lacks
// (sh_l1 / sh_l2 on a file baked before the SH probes: re-bake).
void requireTechniqueData(const std::string& path, const probes::ProbeSet& set,
                          const profile::Profile& p);

} // namespace pb::app
