// probebench respond: how fast the GI follows a scene change under each probe update schedule,
// and what the speed costs (issue 20). The measurement itself is bench::RespondRun (shared with
// `bench --respond`); this command reads its options, the scene and the probe file, and writes
// the JSON, the frames and the report.
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "JsonOption.h"
#include "PlatformOptions.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "bench/respond/RespondReport.h"
#include "bench/respond/RespondRun.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "gl/DebugOutput.h"
#include "image/Image.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace pb::app {
namespace {

struct RespondArgs {
    bool mkdir = false; // --mkdir: create --out-dir's and --json's parent folders
    SceneArgs scene;
    platform::PlatformOptions platform;
    std::string probes;
    bench::RespondSettings run;
    int raysPerFrame = 0;
    long long uploadBytesPerFrame = 0; // 0: no limit
    ProfileArgs profileArgs;           // --profile: switches and its [update] budget
    const CLI::Option *raysOption = nullptr, *bytesOption = nullptr;
    bool force = false;
    std::string outDir;
    JsonOption json;
};

void respondProgress(const std::string& line) {
    std::cerr << "respond: " << line << "\n";
}

int go(RespondArgs& a) {
    if (!a.outDir.empty()) checkOutputFolder("--out-dir", a.outDir, a.mkdir); // OutputPaths.h
    // A profile's update budget applies unless the command line gives one.
    const profile::PlatformProfile platformProfile = resolveProfile(a.profileArgs);
    bench::RespondBudget budget{
        platformProfile.name, platformProfile.switches,
        a.raysOption->count() ? a.raysPerFrame : platformProfile.updateRaysPerFrame,
        a.bytesOption->count() ? a.uploadBytesPerFrame : platformProfile.updateUploadBytesPerFrame};
    if (budget.raysPerFrame < 0) throw UsageError("--rays-per-frame: must not be negative");
    if (budget.uploadBytesPerFrame < 0)
        throw UsageError("--upload-bytes-per-frame: must not be negative");
    scene::Scene scene = loadSceneWithOverrides(a.scene);
    probes::ProbeSet set = readProbesForScene(a.probes, scene, a.force);
    a.run.probesName = a.probes;
    a.run.keepFrames = !a.outDir.empty();
    bench::RespondRun run(std::move(scene), std::move(set), a.run, respondProgress);

    auto platform = platform::createPlatform([&] {
        auto p = a.platform;
        p.width = a.run.width;
        p.height = a.run.height;
        return p;
    }());
    gl::DebugOutput debug;
    bench::RespondFrames pngs;
    const nlohmann::json result = run.measure(budget, debug, &pngs);
    if (!a.outDir.empty()) {
        std::filesystem::create_directories(std::filesystem::path(a.outDir) / "frames");
        for (const auto& [name, images] : pngs)
            for (std::size_t f = 0; f < images.size(); ++f) {
                char file[64];
                std::snprintf(file, sizeof file, "%s_%04zu.png", name.c_str(), f);
                image::writePng((std::filesystem::path(a.outDir) / "frames" / file).string(),
                                images[f]);
            }
        const std::string html = bench::respondReportHtml(result);
        writeFileAtomic((std::filesystem::path(a.outDir) / "report.html").string(), html.data(),
                        html.size());
    }
    if (a.json) writeJson(a.json, result.dump(2) + "\n");
    return 0;
}

const RegisterCommand registerRespond{
    {"respond", "Measure how fast probe updates follow a scene change, per update schedule", 60,
     [](CLI::App& cmd) {
         auto a = std::make_shared<RespondArgs>();
         cmd.footer(
             "Events (--event, repeatable, or [[event]] spec=\"...\" in --timeline FILE):\n"
             "  sun:off@F  sun:on@F  sun:dir:X,Y,Z@F  sun:scale:K@F\n"
             "  light:NAME:off@F  light:NAME:on@F  light:NAME:scale:K@F  light:NAME:move:X,Y,Z@F\n"
             "  node:NAME:remove@F  node:NAME:insert:X,Y,Z@F\n"
             "Sun changes mark every probe; the others the probes within --radius. Each schedule\n"
             "(hysteresis 0.97, rtxgi thresholds, EdenSpark's hastened) runs the same frames;\n"
             "t95/t99 count frames after the last event until the image error against the\n"
             "converged re-bake stays within 5%/1% of the step.");
         addSceneOptions(cmd, a->scene);
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--probes", a->probes, "Dense probe file baked for --scene")->required();
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--scenario", a->run.scenario,
                        "Lighting scenario of --probes (default: its first)");
         cmd.add_option("--event", a->run.events, "A scene change, e.g. sun:off@10 (see below)");
         cmd.add_option("--timeline", a->run.timeline, "TOML file of [[event]] spec = \"...\"");
         cmd.add_option("--frames", a->run.frames, "Frames to run (default 150)");
         cmd.add_option("--schedule", a->run.schedules,
                        "Comma-separated: hysteresis, rtxgi, hastened (default: all three)");
         addProfileOptions(cmd, a->profileArgs,
                           "The profile's [update] rays_per_frame / upload_bytes_per_frame are "
                           "the budget unless --rays-per-frame / --upload-bytes-per-frame say.");
         a->raysOption =
             cmd.add_option("--rays-per-frame", a->raysPerFrame,
                            "Ray budget per frame (0 = update every marked probe every frame)");
         a->bytesOption =
             cmd.add_option("--upload-bytes-per-frame", a->uploadBytesPerFrame,
                            "Upload budget per frame in bytes (0 = no limit); each update uploads "
                            "one 8x8 irradiance tile (512 bytes in rgba16f)");
         cmd.add_option("--rays-per-update", a->run.raysPerUpdate,
                        "Rays per probe and bounce pass of one update's sample (default 256)");
         cmd.add_option("--sample-bakes", a->run.sampleBakes,
                        "Independent sample bakes the updates cycle through (default 16)");
         cmd.add_option("--radius", a->run.radius,
                        "Radius of a local change, scene units (default 1.5)");
         cmd.add_option("--width", a->run.width, "Image width (default 160)");
         cmd.add_option("--height", a->run.height, "Image height (default 90)");
         cmd.add_option("--out-dir", a->outDir, "Folder for frames/*.png and report.html");
         cmd.add_option("--cache-dir", a->run.cacheDir,
                        "Where the converged re-bake is cached (default: the probe cache folder, "
                        "as bench and truth use)");
         cmd.add_flag("--mkdir", a->mkdir, "Create the missing parent folder of --out-dir and --json (else a missing folder is an error, before any work)");
         a->json.add(cmd, "schedules[] with t95_frames, t99_frames, overshoot, flicker, far_drift, "
                          "rays_per_frame, cpu_ms_per_frame, bytes_uploaded, error_curve");
         return [a] { return go(*a); };
     }}};

} // namespace
} // namespace pb::app
