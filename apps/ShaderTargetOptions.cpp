#include "ShaderTargetOptions.h"

#include "bench/runner/PredictionRun.h"

#include "ProfileOptions.h"
#include "bench/shaders/MesaShim.h"
#include "bench/shaders_gl/ShaderPlan.h"
#include "bench/shaders_gl/TargetWorkers.h"
#include "core/Error.h"

#include <filesystem>

namespace pb::app {
namespace {

std::string selfExecutable() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("cannot find the running executable (/proc/self/exe)");
    return p.string();
}

std::string joined(const std::vector<std::string>& list) {
    std::string out;
    for (const std::string& s : list)
        out += (out.empty() ? "" : ",") + s;
    return out;
}

} // namespace

bench::BenchPlan shaderBenchPlan(const ShaderPlanArgs& a) {
    const profile::ProfileSearch search = profileSearch();
    const std::vector<profile::PlatformProfile> profiles =
        loadProfilesWithSets(a.profiles, a.sets, search);
    return bench::makeBenchPlan(profiles, profile::loadProfile(a.reference, search),
                                {a.ablate, a.width, a.height});
}

shaders::ShaderStatisticsRun
runShaderTargets(const ShaderRunInputs& in, const std::string& sceneName,
                 const std::function<void(const std::string&)>& progress) {
    const std::vector<shaders::ShaderTarget> targets = shaders::parseShaderTargets(in.targets);
    const shaders::MesaShimInstall install = shaders::findMesaShim();
    const bench::BenchPlan plan = shaderBenchPlan(in.plan);
    // The worker resolves the same list the same way (a profile file stays a file).
    const std::string profileList = in.plan.profiles.empty() ? "all" : joined(in.plan.profiles);

    shaders::WorkerLaunch launch;
    launch.timeoutSeconds = in.timeoutSeconds;
    launch.argv = {selfExecutable(), "shaders-worker",
                   "--scene",        in.scene.scene,
                   "--probes",       in.probesPath,
                   "--camera",       in.camera,
                   "--profiles",     profileList,
                   "--reference",    in.plan.reference,
                   "--width",        std::to_string(in.plan.width),
                   "--height",       std::to_string(in.plan.height)};
    if (!in.scene.sun.empty()) launch.argv.insert(launch.argv.end(), {"--sun", in.scene.sun});
    if (!in.scene.sky.empty()) launch.argv.insert(launch.argv.end(), {"--sky", in.scene.sky});
    for (const std::string& d : in.scene.dynamicNodes)
        launch.argv.insert(launch.argv.end(), {"--dynamic", d});
    if (in.scene.allowExternalUris) launch.argv.push_back("--allow-external-uris");
    for (const std::string& s : in.plan.sets)
        launch.argv.insert(launch.argv.end(), {"--set", s});
    if (!in.plan.ablate) launch.argv.push_back("--no-ablate");
    if (in.plan.fusedTwins) launch.argv.push_back("--fused-twins");

    shaders::ShaderStatisticsRun run;
    run.mesaVersion = install.mesaVersion;
    run.mesaDir = install.dir;
    run.scene = sceneName;
    run.probes = in.probesPath;
    run.camera = in.camera;
    run.width = in.plan.width;
    run.height = in.plan.height;
    run.pairs = shaders::switchPairs(plan);
    run.targets = shaders::collectOnTargets(targets, install, launch, progress);
    return run;
}

shaders::ShaderStatisticsRun
runModelCompilers(const std::vector<devicemodel::DeviceSpec>& devices, ShaderPlanArgs plan,
                  const SceneArgs& scene, const std::string& probesPath, const std::string& camera,
                  int timeoutSeconds, const std::string& sceneName,
                  const std::function<void(const std::string&)>& progress) {
    ShaderRunInputs in;
    in.targets = bench::predictionTargets(devices);
    plan.fusedTwins = true;
    in.plan = std::move(plan);
    in.scene = scene;
    in.probesPath = probesPath;
    in.camera = camera;
    in.timeoutSeconds = timeoutSeconds;
    if (progress) progress("compiling every variant's programs on " + in.targets);
    return runShaderTargets(in, sceneName, progress);
}

} // namespace pb::app
