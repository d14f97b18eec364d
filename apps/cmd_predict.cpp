// probebench predict: the device model without timing anything here - per profile (and with
// --ablate per switch) the predicted frame, passes and bound units on named devices, from the
// cost model's exact counts and the devices' stand-in compilers (bench/devicemodel/README.md).
// What `bench --predict` puts beside its measurements, for a device at any size in seconds.
#include "CommandRegistry.h"
#include "DeviceOptions.h"
#include "JsonOption.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/report/DevicePrediction.h"
#include "bench/runner/PredictionRun.h"
#include "bench/runner/ProbeCache.h"
#include "bench/shaders/MesaShim.h"
#include "core/Error.h"
#include "views/WorstCaseView.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace pb::app {
namespace {

struct PredictArgs {
    SceneArgs scene;
    bool force = false, ablate = false;
    std::vector<std::string> profiles, sets;
    std::string reference = "reference", devices, view, camera, probes, volumes = "auto", cacheDir;
    int width = 0, height = 0, timeout = 600;
    JsonOption json;
};

void say(const std::string& line) {
    std::fprintf(stderr, "predict: %s\n", line.c_str());
    std::fflush(stderr);
}

int runPredict(const PredictArgs& a) {
    if ((a.width > 0) != (a.height > 0)) throw Error("--width and --height go together");
    if (a.width < 0 || a.height < 0 || a.width > 16384 || a.height > 16384 ||
        (a.width > 0 && (a.width < 16 || a.height < 16)))
        throw UsageError("--width/--height must be in 16..16384");
    if (!a.view.empty() && !a.camera.empty()) throw Error("give --view or --camera, not both");
    const profile::ProfileSearch search = profileSearch();
    const profile::PlatformProfile reference = profile::loadProfile(a.reference, search);
    const std::vector<profile::PlatformProfile> profiles =
        loadProfilesWithSets(a.profiles, a.sets, search);
    const bench::BenchPlan plan =
        bench::makeBenchPlan(profiles, reference, {a.ablate, a.width, a.height});
    const std::vector<devicemodel::DeviceSpec> devices = resolvePredictDevices(a.devices, profiles);
    shaders::findMesaShim();

    const scene::Scene s = loadSceneWithOverrides(a.scene);
    std::string probesPath = a.probes;
    const probes::ProbeSet set =
        a.probes.empty()
            ? bench::benchProbes(s, a.volumes,
                                 a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir,
                                 &probesPath, say)
            : readProbesForScene(a.probes, s, a.force);
    scene::View view;
    if (!a.camera.empty() || !a.view.empty()) {
        view = chooseView(s, a.view, a.camera);
    } else {
        const bench::Session& first = plan.sessions.front();
        const int h = std::min(first.height, 180);
        const int w = std::max(16, int(double(first.width) * h / first.height + 0.5));
        say("searching the worst-case view at " + std::to_string(w) + "x" + std::to_string(h));
        view = views::findWorstCaseView(s, set, w, h).view;
    }
    const shaders::ShaderStatisticsRun stats =
        runModelCompilers(devices, {a.profiles, a.reference, a.sets, a.ablate}, a.scene,
                          probesPath, cameraSpec(view), a.timeout, s.name, say);
    const std::vector<bench::DevicePrediction> p = bench::predictDevices(
        plan, s, set, view, stats, {devices, a.devices == "own", true, say});

    std::cout << "Scene " << s.name << ", camera " << cameraSpec(view) << ", probes " << probesPath
              << ", compilers of Mesa " << stats.mesaVersion << ".\n";
    std::cout << bench::predictionsMarkdown(p);
    if (a.json)
        writeJson(a.json, nlohmann::json{{"scene", s.name},
                                         {"camera", cameraSpec(view)},
                                         {"probes", probesPath},
                                         {"device_model", bench::predictionsJson(p)}}
                              .dump(2) + "\n");
    int failed = 0;
    for (const bench::DevicePrediction& d : p) {
        if (!d.error.empty()) {
            std::fprintf(stderr, "error: model: %s: %s\n", d.device.c_str(), d.error.c_str());
            failed = 1;
        }
        for (const bench::PredictedSession& ps : d.sessions)
            for (const bench::PredictedVariant& v : ps.variants)
                if (!v.error.empty())
                    std::fprintf(stderr, "warning: model: %s: %s not predicted: %s\n",
                                 d.device.c_str(), v.id.c_str(), v.error.c_str());
    }
    return failed;
}

const RegisterCommand registerPredict{
    {"predict",
     "Predict each profile's frame time, passes and switch deltas on named devices (the device "
     "model; nothing timed here)",
     52, [](CLI::App& cmd) {
         auto a = std::make_shared<PredictArgs>();
         addSceneOptions(cmd, a->scene);
         cmd.add_option("--device,--devices", a->devices,
                        "Devices: NAME[,NAME...] (probebench devices), all, or own (each profile "
                        "on the device its [budget] model names)")
             ->required();
         cmd.add_option("--profiles,--profile", a->profiles,
                        "Profiles, comma-separated names or .toml files (default: all)")
             ->delimiter(',');
         cmd.add_option("--reference", a->reference, "The profile the deltas compare with")
             ->capture_default_str();
         cmd.add_option("--set", a->sets,
                        "Switch key=value applied to every profile, not to the reference (repeatable)");
         cmd.add_flag("--ablate", a->ablate,
                      "Per switch where a profile differs from the reference: its predicted delta "
                      "(as bench --ablate)");
         cmd.add_option("--width", a->width, "Predict every profile at this width instead of its own");
         cmd.add_option("--height", a->height, "...and this height");
         cmd.add_option("--view", a->view, "A named view of the scene instead of the worst case");
         cmd.add_option("--camera", a->camera,
                        "Camera px,py,pz,tx,ty,tz[,fovdeg] instead of the worst case");
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--probes", a->probes, "Probe file; default: the bench's bake of --volumes (cached)");
         cmd.add_option("--volumes", a->volumes, "Without --probes: the volumes to bake (as bench)")
             ->capture_default_str();
         cmd.add_option("--cache-dir", a->cacheDir,
                        "Folder of the baked-probe cache (default: ~/.cache/probebench)");
         cmd.add_option("--timeout", a->timeout, "Seconds one compiler's worker may take")
             ->capture_default_str();
         a->json.add(cmd, "Every prediction with its per-unit demand");
         cmd.footer("Needs the weak GPUs' compilers (scripts/mesa-shim.sh). The figures are a model, "
                    "deterministic on any machine; bench/devicemodel/README.md says what it counts "
                    "and what it leaves out.");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runPredict(*a);
         };
     }}};

} // namespace
} // namespace pb::app
