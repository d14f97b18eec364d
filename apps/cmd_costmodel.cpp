// probebench costmodel: the deterministic cost model of the GI apply pass for one view -
// counters (pixels per volume, fetches, bytes, draws and binds, probe GPU memory) and each
// shader variant's texel stream through texture-cache models (hit rate, bytes missed per
// pixel). Hardware-independent: what a testbed without the target GPU can say about it.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "profile/GiVolumeLod.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/VolumeRanksFile.h"

#include <cstdio>
#include <iostream>

namespace pb::app {
namespace {

struct CostArgs {
    bool force = false; // --probes baked for another scene
    SceneArgs scene;
    std::string probes, view, camera, scenario, layout = "tiled";
    ProfileArgs profileArgs;
    std::vector<std::string> cachePresets;
    const CLI::Option *widthOption = nullptr, *heightOption = nullptr;
    std::uint64_t cacheSize = 0;
    int line = 0, ways = 0, tile = 8, warp = 32, inFlight = 4;
    int width = 1280, height = 720;
    JsonOption json;
    bool worstCase = false;
};

std::string costModelCameraSpec(const scene::View& v) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", v.position.x, v.position.y,
                  v.position.z, v.target.x, v.target.y, v.target.z, v.fovYDegrees);
    return buf;
}

std::vector<costmodel::CacheConfig> chooseCaches(const CostArgs& a,
                                                 const profile::PlatformProfile& prof) {
    std::vector<costmodel::CacheConfig> out;
    for (const std::string& name : a.cachePresets)
        out.push_back(costmodel::cachePresetFor(name));
    const bool custom = a.cacheSize || a.line || a.ways;
    if (custom) {
        if (!a.cacheSize || !a.line || !a.ways)
            throw Error("--cache-size, --line and --ways go together (all three or none)");
        costmodel::CacheConfig c{"custom", a.cacheSize, a.line, a.ways, "command line"};
        c.validate();
        out.push_back(c);
    }
    // With --profile and no cache named: the profile's own preset.
    if (out.empty() && !a.profileArgs.profile.empty())
        out.push_back(costmodel::cachePresetFor(prof.cachePreset));
    return out; // empty: every preset
}

int runCostmodel(CostArgs& a) {
    const profile::PlatformProfile platformProfile = resolveProfile(a.profileArgs);
    if (!a.profileArgs.profile.empty()) { // the profile's resolution unless given
        if (a.widthOption->count() == 0) a.width = platformProfile.width;
        if (a.heightOption->count() == 0) a.height = platformProfile.height;
    }
    if (a.width < 1 || a.height < 1 || a.width > 16384 || a.height > 16384)
        throw UsageError("--width/--height must be in 1..16384");
    if (a.worstCase && (!a.view.empty() || !a.camera.empty()))
        throw Error("--worst-case searches a camera: leave out --view and --camera");
    if (a.tile < 2 || a.tile > 64 || a.tile % 2) throw UsageError("--tile must be even, in 2..64");
    costmodel::CostModelOptions o;
    o.profile = platformProfile.switches;
    o.width = a.width;
    o.height = a.height;
    o.tile = a.tile;
    if (a.warp < 1 || a.warp > 1024) throw UsageError("--warp must be in 1..1024 pixels");
    if (a.inFlight < 1 || a.inFlight > 256) throw UsageError("--warps-in-flight must be in 1..256");
    o.warpPixels = a.warp;
    o.warpsInFlight = a.inFlight;
    o.layout = costmodel::parseMemoryLayout(a.layout);
    o.caches = chooseCaches(a, platformProfile);
    scene::Scene s = loadSceneWithOverrides(a.scene);
    probes::ProbeSet set = readProbesForScene(a.probes, s, a.force);
    if (!a.scenario.empty()) {
        o.scenario = set.findScenario(a.scenario);
        if (o.scenario < 0) throw Error("--scenario '" + a.scenario + "': not in " + a.probes);
    }
    std::vector<bool> kept(set.volumes.size(), false);
    for (int v : profile::selectVolumes(set, profile::parseVolumeLod(o.profile.gi.volumeLod)))
        kept[size_t(v)] = true;
    const views::CoverageTester tester(s, set, kept);
    scene::View view;
    if (a.worstCase) {
        view = views::findWorstCaseView(tester, a.width, a.height).view;
    } else {
        view = chooseView(s, a.view, a.camera);
        if (!a.camera.empty()) view.name = "camera";
    }
    costmodel::CostReport r = costmodel::runCostModel(tester, view, o);
    r.scene = s.name;
    r.view = view.name;
    r.camera = costModelCameraSpec(view);
    if (a.json)
        writeJson(a.json, costmodel::reportJson(r).dump(2) + "\n");
    else
        std::cout << costmodel::reportText(r) << "  --camera " << r.camera << "\n";
    return 0;
}

const RegisterCommand registerCostmodel{
    {"costmodel",
     "Deterministic GI pass counters and a texture-cache model per shader variant (no GPU)", 47,
     [](CLI::App& cmd) {
         auto a = std::make_shared<CostArgs>();
         addSceneOptions(cmd, a->scene);
         cmd.add_option("--probes", a->probes, "Probe file (probebench bake)")->required();
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--view", a->view, "Named view of the scene (default: its first)");
         cmd.add_option("--camera", a->camera, "Camera px,py,pz,tx,ty,tz[,fovdeg]");
         cmd.add_flag("--worst-case", a->worstCase,
                      "Use the worst-case view (probebench views --worst-case)");
         addProfileOptions(cmd, a->profileArgs,
                           "gi.resolution, gi.target_format and gi.volume_lod count; "
                           "gi.probe_order/gi.loops mark the profile's variant; --profile also "
                           "picks its cache preset and resolution.");
         cmd.add_option("--scenario", a->scenario, "Lighting scenario (default: the file's first)");
         cmd.add_option("--cache", a->cachePresets,
                        "Cache preset, repeatable: handheld, console-base, pc-low, pc-high "
                        "(default: the --profile's preset, else all, unless a custom cache is "
                        "given)");
         cmd.add_option("--cache-size", a->cacheSize, "Custom cache: size in bytes (power of 2)");
         cmd.add_option("--line", a->line, "Custom cache: line size in bytes (power of 2)");
         cmd.add_option("--ways", a->ways, "Custom cache: associativity");
         cmd.add_option("--layout", a->layout,
                        "Texture memory layout: tiled (4 KiB Morton tiles) or linear (rows)")
             ->capture_default_str();
         cmd.add_option("--tile", a->tile, "Pixel tile of the shading order (2x2 quads inside)")
             ->capture_default_str();
         cmd.add_option("--warp", a->warp,
                        "Pixels per SIMD group (warp/wave) issuing each fetch together")
             ->capture_default_str();
         cmd.add_option("--warps-in-flight", a->inFlight,
                        "Warps taking turns per fetch instruction through one cache "
                        "(1 with --warp 1: pixel after pixel)")
             ->capture_default_str();
         a->widthOption = cmd.add_option("--width", a->width,
                                         "Frame (GBuffer) width (default: the --profile's, "
                                         "else 1280)");
         a->heightOption = cmd.add_option("--height", a->height,
                                          "Frame (GBuffer) height (default: the --profile's, "
                                          "else 720)");
         a->json.add(cmd, "The counters and the cache model");
         return [a] { return runCostmodel(*a); };
     }}};

} // namespace
} // namespace pb::app
