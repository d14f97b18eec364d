#pragma once
// The worker's side of `probebench shaders`: on the current GL context (a target's driver
// behind its shim), build each planned variant's frame renderer and render one frame, so that
// every pass asks the program cache for exactly the programs it uses in production; every
// program built is attributed to the pass (frame section) that asked for it and to the
// variant, with the statistics the driver reported while compiling and linking it.
//
// Drivers print statistics of the variant they compile at link time (Mesa's state tracker
// always builds a default variant then; freedreno and v3d need their precompile switches,
// ShaderTargets.cpp). Recompiles at draw time (other keys) are not counted: one program, one
// set of figures, as shader-db reports them.
#include "bench/shaders/ShaderStatistics.h"
#include "gl/DebugOutput.h"
#include "probes/ProbeSet.h"
#include "profile/Profile.h"
#include "scene/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::shaders {

struct PlannedVariant {
    VariantStatistics meta; // id, label, profile, role, switch (programs filled by collecting)
    profile::Profile switches;
};

struct CollectInputs {
    const scene::Scene* scene = nullptr;
    const probes::ProbeSet* probes = nullptr;
    scene::View view;
    int width = 160, height = 90;
};

// Renders one frame per variant. A variant the renderer rejects (a format or feature the
// context lacks, data the probe file lacks) or whose program the driver rejects gets `notRun`;
// the others go on. Fills GL strings, programs and variants; target identity stays empty.
TargetStatistics collectShaderStatistics(const CollectInputs& in,
                                         const std::vector<PlannedVariant>& variants,
                                         gl::DebugOutput& debug,
                                         const std::function<void(const std::string&)>& progress);

} // namespace pb::shaders
