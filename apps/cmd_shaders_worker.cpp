// probebench shaders-worker: one target's side of `probebench shaders` (hidden). Runs in a
// process whose environment selects the target's driver (bench/shaders/MesaShim.h): builds
// every variant of the plan once on an EGL context and writes the statistics the driver
// reported to --out as JSON.
#include "CommandRegistry.h"
#include "ProbeOptions.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/shaders_gl/ShaderCollector.h"
#include "bench/shaders_gl/ShaderPlan.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "gl/DebugOutput.h"
#include "platforms/Platform.h"

#include <cstdio>

namespace pb::app {
namespace {

struct ShadersWorkerArgs {
    SceneArgs scene;
    ShaderPlanArgs plan;
    bool noAblate = false;
    std::string probes, camera, out;
};

int runShadersWorker(ShadersWorkerArgs& a) {
    a.plan.ablate = !a.noAblate;
    const bench::BenchPlan plan = shaderBenchPlan(a.plan);
    const scene::Scene s = loadSceneWithOverrides(a.scene);
    const probes::ProbeSet set = readProbesForScene(a.probes, s, true);
    platform::PlatformOptions po;
    po.name = "egl";
    const auto platform = platform::createPlatform(po);
    gl::DebugOutput debug;
    shaders::CollectInputs in;
    in.scene = &s;
    in.probes = &set;
    in.view = chooseView(s, "", a.camera);
    in.width = a.plan.width;
    in.height = a.plan.height;
    const shaders::TargetStatistics t = shaders::collectShaderStatistics(
        in, shaders::plannedVariants(plan, a.plan.fusedTwins), debug, [](const std::string& line) {
            std::fprintf(stderr, "shaders-worker: %s\n", line.c_str());
        });
    const std::string text = shaders::toJson(t).dump(1) + "\n";
    writeFileAtomic(a.out, text.data(), text.size());
    return 0;
}

const RegisterCommand registerShadersWorker{
    {"shaders-worker", "Internal: one target's compiler run of `probebench shaders`", 1000,
     [](CLI::App& cmd) {
         cmd.group(""); // hidden from `probebench --help`
         auto a = std::make_shared<ShadersWorkerArgs>();
         addSceneOptions(cmd, a->scene);
         cmd.add_option("--probes", a->probes, "Probe file")->required();
         cmd.add_option("--camera", a->camera, "Camera px,py,pz,tx,ty,tz[,fovdeg]")->required();
         cmd.add_option("--profiles", a->plan.profiles, "Profiles, or all")->delimiter(',');
         cmd.add_option("--reference", a->plan.reference, "The reference profile");
         cmd.add_option("--set", a->plan.sets, "Switch key=value on every profile");
         cmd.add_flag("--no-ablate", a->noAblate, "No single-switch variants");
         cmd.add_flag("--fused-twins", a->plan.fusedTwins,
                      "Also each gi.loops=split variant with fused loops (the device model's ALU "
                      "figure)");
         cmd.add_option("--width", a->plan.width, "Frame width");
         cmd.add_option("--height", a->plan.height, "Frame height");
         cmd.add_option("--out", a->out, "The JSON result")->required();
         return [a] { return runShadersWorker(*a); };
     }}};

} // namespace
} // namespace pb::app
