#pragma once
// What `probebench shaders` and `bench --targets` share: the plan the workers compile (the
// bench's plan, ablation included), the worker command line both re-execute probebench with,
// and the run across targets. The measuring itself is bench/shaders_gl's.
#include "SceneOptions.h"
#include "bench/report/AblationPlan.h"
#include "bench/devicemodel/DeviceSpec.h"
#include "bench/shaders/ShaderStatistics.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::app {

struct ShaderPlanArgs {
    std::vector<std::string> profiles; // names or files; empty or "all": every profile
    std::string reference = "reference";
    std::vector<std::string> sets;
    bool ablate = true;
    bool fusedTwins = false; // each split-loops variant's fused twin too (ShaderPlan.h)
    int width = 160, height = 90; // the frame each variant renders once to build its programs
};

bench::BenchPlan shaderBenchPlan(const ShaderPlanArgs& a);

struct ShaderRunInputs {
    std::string targets; // --targets: "all" or names
    ShaderPlanArgs plan;
    SceneArgs scene;
    std::string probesPath; // the probe file every worker reads
    std::string camera;     // px,py,pz,tx,ty,tz,fov: every worker renders this view
    int timeoutSeconds = 600;
};

// One worker per target (`probebench shaders-worker` under the target's environment); the
// Mesa install is found first (pb::Error with the build command when there is none).
shaders::ShaderStatisticsRun
runShaderTargets(const ShaderRunInputs& in, const std::string& sceneName,
                 const std::function<void(const std::string&)>& progress);

// The compilers the device model needs for `devices` (bench::predictionTargets: each device's
// stand-in and ir3's texture counts), every variant of `plan` with its fused twin.
shaders::ShaderStatisticsRun
runModelCompilers(const std::vector<devicemodel::DeviceSpec>& devices, ShaderPlanArgs plan,
                  const SceneArgs& scene, const std::string& probesPath, const std::string& camera,
                  int timeoutSeconds, const std::string& sceneName,
                  const std::function<void(const std::string&)>& progress);

} // namespace pb::app
