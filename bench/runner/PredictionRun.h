#pragma once
// `bench --predict`: the device model's predictions (bench/devicemodel) for every session of the
// bench's plan on each device - per variant the cost model's replay of the GI pass through the
// device's L2 (once per distinct replay, every device's caches in the same run), each pass's
// program cost from the device's stand-in compiler (the shader statistics run, with fused
// twins), the renderer's fixed facts - and per planned delta the predicted on - off. Measured
// figures are attached later (report/PredictionMeasured.h). GL-free apart from the facts.
#include "bench/devicemodel/DeviceSpec.h"
#include "bench/report/AblationPlan.h"
#include "bench/report/DevicePrediction.h"
#include "bench/shaders/ShaderStatistics.h"
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::bench {

struct PredictionRequest {
    std::vector<devicemodel::DeviceSpec> devices;
    // Each session only on the device its profile names ([budget] model); sessions without
    // one are left out. Otherwise every session on every device.
    bool ownDevicesOnly = false;
    // On its own device, the profile also at its own output size when the session runs at
    // another (the budget's frame). The gate, which keeps the suite's size only, turns it off.
    bool budgetFrames = true;
    std::function<void(const std::string&)> progress;
};

// `stats` must hold each device's compiler target and "adreno-630" (ir3's texture counts),
// compiled from the same profiles with fused twins (ShaderPlanArgs::fusedTwins).
std::vector<DevicePrediction> predictDevices(const BenchPlan& plan, const scene::Scene& scene,
                                             const probes::ProbeSet& set, const scene::View& view,
                                             const shaders::ShaderStatisticsRun& stats,
                                             const PredictionRequest& request);

// The compiler targets a prediction needs: each device's, and adreno-630 (ir3's texture
// instruction counts), comma-separated, each once.
std::string predictionTargets(const std::vector<devicemodel::DeviceSpec>& devices);

} // namespace pb::bench
