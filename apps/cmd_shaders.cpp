// probebench shaders: every pass's program of every profile (and of the ablation's
// single-switch variants) compiled by the weak GPUs' own compilers - Mesa's freedreno
// (Adreno), panfrost (Mali), v3d (Raspberry Pi 4) and nouveau (Tegra X1) drivers behind their
// drm-shims, built by scripts/mesa-shim.sh - with the statistics each compiler reports:
// instructions, cycle bounds per unit, registers, threads or waves, spills. Markdown on
// stdout, JSON with --json. bench/shaders/README.md.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "OutputPaths.h"
#include "ProbeOptions.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/runner/ProbeCache.h"
#include "bench/shaders/MesaShim.h"
#include "bench/shaders/ShaderTables.h"
#include "bench/shaders_gl/TargetWorkers.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "views/WorstCaseView.h"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace pb::app {
namespace {

struct ShadersArgs {
    bool listTargets = false, noAblate = false, force = false;
    std::string exec;                     // --exec TARGET
    std::vector<std::string> execCommand; // after --
    ShaderRunInputs run;
    std::string view, volumes = "auto", cacheDir, markdown;
    JsonOption json;
};

void progress(const std::string& line) {
    std::fprintf(stderr, "shaders: %s\n", line.c_str());
    std::fflush(stderr);
}

int listTargets(const JsonOption& json) {
    std::string installError;
    shaders::MesaShimInstall install;
    try {
        install = shaders::findMesaShim();
    } catch (const Error& e) {
        installError = e.what();
    }
    nlohmann::json list = nlohmann::json::array();
    for (const shaders::ShaderTarget& t : shaders::shaderTargets()) {
        const std::string why =
            installError.empty() ? shaders::targetUnavailableReason(t, install) : "not built";
        list.push_back({{"name", t.name},
                        {"device", t.device},
                        {"driver", t.driver},
                        {"environment", t.env},
                        {"built", why.empty()},
                        {"note", t.note}});
    }
    if (json) {
        writeJson(json, nlohmann::json({{"mesa_version", install.mesaVersion},
                                        {"mesa_dir", install.dir},
                                        {"targets", list}})
                                .dump(2) +
                            "\n");
        return 0;
    }
    std::printf("%-13s %-42s %-10s %-6s %s\n", "target", "device", "driver", "built",
                "environment");
    for (const nlohmann::json& t : list) {
        std::string env;
        for (const auto& e : t["environment"])
            env += (env.empty() ? "" : " ") + e.get<std::string>();
        std::printf("%-13s %-42s %-10s %-6s %s\n", t["name"].get<std::string>().c_str(),
                    t["device"].get<std::string>().c_str(), t["driver"].get<std::string>().c_str(),
                    t["built"] ? "yes" : "no", env.c_str());
    }
    if (installError.empty())
        std::printf("\nMesa %s in %s\n", install.mesaVersion.c_str(), install.dir.c_str());
    else
        std::printf("\n%s\n", installError.c_str());
    return 0;
}

// Replaces this process with `command` under the target's environment (for the compile tests
// on every target: `probebench shaders --exec mali-g52 -- build/tests/gl_tests ...`).
int execOnTarget(const ShadersArgs& a) {
    if (a.execCommand.empty()) throw Error("--exec " + a.exec + ": no command after --");
    const shaders::ShaderTarget& target = shaders::findShaderTarget(a.exec);
    const shaders::MesaShimInstall install = shaders::findMesaShim();
    if (std::string why = shaders::targetUnavailableReason(target, install); !why.empty())
        throw Error("--exec " + a.exec + ": " + why);
    for (const std::string& e : shaders::targetEnvironment(target, install)) {
        const size_t eq = e.find('=');
        setenv(e.substr(0, eq).c_str(), e.substr(eq + 1).c_str(), 1);
    }
    std::vector<char*> argv;
    for (const std::string& s : a.execCommand)
        argv.push_back(const_cast<char*>(s.c_str()));
    argv.push_back(nullptr);
    std::fflush(nullptr);
    execvp(argv[0], argv.data());
    throw Error("--exec " + a.exec + ": cannot run " + a.execCommand[0]);
}

int runShaders(ShadersArgs& a) {
    if (a.listTargets) return listTargets(a.json);
    if (!a.exec.empty()) return execOnTarget(a);
    if (a.run.targets.empty())
        throw Error("--targets: name the targets (or all; --list-targets lists them)");
    if (a.run.plan.width < 16 || a.run.plan.height < 16 || a.run.plan.width > 4096 ||
        a.run.plan.height > 4096)
        throw UsageError("--width/--height must be in 16..4096");
    if (a.run.timeoutSeconds < 1) throw UsageError("--timeout must be at least 1 s");
    if (!a.view.empty() && !a.run.camera.empty()) throw Error("give --view or --camera, not both");
    a.run.plan.ablate = !a.noAblate;
    // Everything that can be wrong is said before the bake: names, the install, the plan.
    shaders::parseShaderTargets(a.run.targets);
    shaders::findMesaShim();
    shaderBenchPlan(a.run.plan);
    if (!a.json.file().empty()) checkOutputFile("--json", a.json.file(), {".json"}, "JSON", false);
    if (!a.markdown.empty()) checkOutputFile("--markdown", a.markdown, {".md"}, "Markdown", false);

    const scene::Scene s = loadSceneWithOverrides(a.run.scene);
    probes::ProbeSet set;
    if (a.run.probesPath.empty()) {
        set = bench::benchProbes(s, a.volumes,
                                 a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir,
                                 &a.run.probesPath, progress);
    } else {
        set = readProbesForScene(a.run.probesPath, s, a.force);
    }
    if (a.run.camera.empty()) {
        if (!a.view.empty()) {
            a.run.camera = cameraSpec(chooseView(s, a.view, ""));
        } else {
            progress("searching the worst-case view (every pixel needs GI)");
            a.run.camera = cameraSpec(views::findWorstCaseView(s, set, 160, 90).view);
        }
    }
    const shaders::ShaderStatisticsRun run = runShaderTargets(a.run, s.name, progress);
    const std::string md = shaders::shaderMarkdown(run);
    if (!a.markdown.empty()) writeFileAtomic(a.markdown, md.data(), md.size());
    if (a.json) writeJson(a.json, shaders::toJson(run).dump(2) + "\n");
    std::cout << md;
    const std::vector<std::string> problems = shaders::shaderRunProblems(run);
    for (const std::string& p : problems)
        std::fprintf(stderr, "probebench: shaders: %s\n", p.c_str());
    return problems.empty() ? 0 : 1;
}

const RegisterCommand registerShaders{
    {"shaders",
     "Compile every profile's programs with the weak GPUs' own compilers (Mesa's Adreno, Mali, "
     "VideoCore, Tegra drivers under drm-shim) and report their statistics",
     55, [](CLI::App& cmd) {
         auto a = std::make_shared<ShadersArgs>();
         a->run.scene.scene = "rooms";
         cmd.footer("\nThe compilers are built once by scripts/mesa-shim.sh (Debian's Mesa "
                    "source; about 10 min on 2 cores) into /var/cache/probebench/mesa-shim "
                    "($PB_MESA_SHIM_ROOT; $PB_MESA_SHIM_DIR names one install). Figures are the "
                    "compilers' static estimates, not timings (bench/shaders/README.md).");
         cmd.add_flag("--list-targets", a->listTargets,
                      "List the targets: device, Mesa driver, model id, and whether it is built");
         cmd.add_option("--targets", a->run.targets,
                        "Targets, comma-separated (adreno-630,mali-g52,...) or all");
         cmd.add_option("--profiles,--profile", a->run.plan.profiles,
                        "Profiles, comma-separated names or .toml files, or all (default)")
             ->delimiter(',');
         cmd.add_option("--reference", a->run.plan.reference,
                        "The profile the ablation compares with")
             ->capture_default_str();
         cmd.add_option("--set", a->run.plan.sets,
                        "Switch key=value applied to every profile, not to the reference "
                        "(repeatable)");
         cmd.add_flag("--no-ablate", a->noAblate,
                      "Only the profiles and the reference, not the single-switch variants");
         addSceneOptions(cmd, a->run.scene);
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--probes", a->run.probesPath,
                        "Probe file; default: the bench's bake of --volumes (cached)");
         cmd.add_option("--volumes", a->volumes,
                        "Without --probes: the volumes to bake (as bench --volumes)")
             ->capture_default_str();
         cmd.add_option("--cache-dir", a->cacheDir,
                        "Folder of the baked-probe cache (default: ~/.cache/probebench)");
         cmd.add_option("--view", a->view, "A named view instead of the worst case");
         cmd.add_option("--camera", a->run.camera,
                        "Camera px,py,pz,tx,ty,tz[,fovdeg] instead of the worst case");
         cmd.add_option("--width", a->run.plan.width,
                        "Size of the one frame each variant renders to build its programs")
             ->capture_default_str();
         cmd.add_option("--height", a->run.plan.height, "...and its height")->capture_default_str();
         cmd.add_option("--timeout", a->run.timeoutSeconds,
                        "Seconds one target's worker may take before it is stopped")
             ->capture_default_str();
         a->json.add(cmd, "Every program's statistics per target, and the switch pairs");
         cmd.add_option("--markdown", a->markdown, "Also write the Markdown tables to this file");
         cmd.add_option("--exec", a->exec,
                        "Run the command after -- under this target's environment (its driver "
                        "and shim) instead; for tests");
         cmd.add_option("command", a->execCommand, "With --exec: the command and its arguments");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runShaders(*a);
         };
     }}};

} // namespace
} // namespace pb::app
