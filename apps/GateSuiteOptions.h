#pragma once
// The suite options of `probebench gate` (what a baseline measures), valid with --update
// only: a baseline is re-measured exactly as it was recorded, so a run cannot silently
// compare different frames.
#include "bench/gate/GateRecord.h"
#include "scene/Scene.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace pb::app {

struct GateSuiteArgs {
    std::string scene, volumes, camera;
    int width = 0, height = 0;
    std::vector<std::string> profiles;
    std::vector<std::string> shaderTargets;  // "none" alone: gate no shader statistics
    std::vector<const CLI::Option*> options; // to tell which were given
};

void addGateSuiteOptions(CLI::App& cmd, GateSuiteArgs& a);

// The suite of the baseline (or the defaults, every profile, when there is none) with the
// given options applied. Throws pb::Error naming the option when one is given without
// --update, or a value is out of range.
gate::GateSuite resolveGateSuite(const GateSuiteArgs& a, bool update,
                                 const gate::GateSuite* baseline,
                                 const std::vector<std::string>& allProfiles);

// A volumes file named relative to the repository (bench/volumes/...) is found from the
// working folder or from the source tree; auto and auto-uniform pass through.
std::string resolveSuiteVolumes(const std::string& volumes);

} // namespace pb::app
