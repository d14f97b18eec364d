#include "GateSuiteOptions.h"
#include "SceneOptions.h"

#include "bench/shaders/ShaderTargets.h"
#include "core/Error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#ifndef PB_SOURCE_DIR
#define PB_SOURCE_DIR "."
#endif

namespace pb::app {

namespace fs = std::filesystem;

void addGateSuiteOptions(CLI::App& cmd, GateSuiteArgs& a) {
    const char* g = "Suite (with --update; otherwise the baseline's)";
    a.options = {
        cmd.add_option("--scene", a.scene, "Scene of the suite (default: rooms)")->group(g),
        cmd.add_option("--volumes", a.volumes,
                       "Probe volumes to bake: a volumes file, auto or auto-uniform (default: "
                       "bench/baselines/rooms_gate.toml)")
            ->group(g),
        cmd.add_option("--camera", a.camera,
                       "Camera px,py,pz,tx,ty,tz[,fovdeg] (default: the worst-case view, searched "
                       "once and stored)")
            ->group(g),
        cmd.add_option("--width", a.width, "Frame width of every profile (default: 384)")->group(g),
        cmd.add_option("--height", a.height, "Frame height (default: 216)")->group(g),
        cmd.add_option("--profiles", a.profiles,
                       "Profiles to gate, comma-separated (default: every profile; the reference "
                       "is always included)")
            ->delimiter(',')
            ->group(g),
        cmd.add_option("--shader-targets", a.shaderTargets,
                       "Shader compiler targets whose statistics are gated, comma-separated, or "
                       "none (default: adreno-630,mali-g52,mali-g57; probebench shaders "
                       "--list-targets)")
            ->delimiter(',')
            ->group(g)};
}

gate::GateSuite resolveGateSuite(const GateSuiteArgs& a, bool update,
                                 const gate::GateSuite* baseline,
                                 const std::vector<std::string>& allProfiles) {
    for (const CLI::Option* o : a.options)
        if (o->count() > 0 && !update)
            throw Error(o->get_name() + ": only with --update (the suite is the baseline's)");
    gate::GateSuite s = baseline ? *baseline : gate::GateSuite{};
    if (!baseline) s.profiles = allProfiles;
    if (!a.scene.empty()) s.scene = a.scene;
    if (!a.volumes.empty()) s.volumes = a.volumes;
    if (!a.camera.empty()) s.camera = a.camera;
    if ((a.width > 0) != (a.height > 0)) throw Error("--width and --height go together");
    if (a.width > 0) {
        if (a.width < 16 || a.height < 16 || a.width > 16384 || a.height > 16384)
            throw UsageError("--width/--height must be in 16..16384");
        s.width = a.width;
        s.height = a.height;
    }
    if (!a.profiles.empty()) s.profiles = a.profiles;
    if (a.shaderTargets == std::vector<std::string>{"none"})
        s.shaderTargets.clear();
    else if (!a.shaderTargets.empty()) {
        s.shaderTargets.clear();
        for (const std::string& t : a.shaderTargets) // throws naming the closest names
            s.shaderTargets.push_back(shaders::findShaderTarget(t).name);
    }
    if (std::find(s.profiles.begin(), s.profiles.end(), s.reference) == s.profiles.end())
        s.profiles.insert(s.profiles.begin(), s.reference);
    return s;
}

std::string resolveSuiteVolumes(const std::string& volumes) {
    if (volumes == "auto" || volumes == "auto-uniform") return volumes;
    if (fs::exists(volumes) || fs::path(volumes).is_absolute()) return volumes;
    const fs::path inSource = fs::path(PB_SOURCE_DIR) / volumes;
    if (fs::exists(inSource)) return inSource.string();
    throw Error("suite volumes " + volumes + ": not found here nor in " + PB_SOURCE_DIR);
}

} // namespace pb::app
