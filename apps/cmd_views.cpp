// probebench views: how much of a camera's image needs GI (pixels seeing geometry inside a
// probe volume), for the scene's named views, a given camera, or the worst-case view the
// benchmark uses (--worst-case: every pixel needs GI, no sky, no early-out).
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "profile/GiVolumeLod.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/VolumeRanksFile.h"
#include "profile/Profile.h"
#include "views/WorstCaseView.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

namespace pb::app {
namespace {

struct ViewsArgs {
    bool force = false; // --probes baked for another scene
    SceneArgs scene;
    std::string probes, view, camera;
    ProfileArgs profileArgs;
    int width = 1280, height = 720;
    const CLI::Option *widthOption = nullptr, *heightOption = nullptr;
    float fov = 60.0f;
    JsonOption json;
    bool worstCase = false;
    double minCoverage = -1.0; // < 0: no requirement
};

// The --camera form of a view, so a found camera can be pasted into render/bench.
std::string viewsCameraSpec(const scene::View& v) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", v.position.x, v.position.y,
                  v.position.z, v.target.x, v.target.y, v.target.z, v.fovYDegrees);
    return buf;
}

nlohmann::json viewJson(const scene::View& v, const views::Coverage& c) {
    return {{"name", v.name},
            {"camera", viewsCameraSpec(v)},
            {"coverage",
             {{"fraction", c.fraction},
              {"max_overlap", c.maxOverlap},
              {"mean_overlap", c.meanOverlap},
              {"mean_distance", c.meanDistance},
              {"dynamic_fraction", c.dynamicFraction}, // pixels on dynamic objects (issue 18)
              {"width", c.width},
              {"height", c.height}}}};
}

void printRow(const std::string& name, const views::Coverage& c) {
    std::printf("  %-20s %9.4f %12d %13.2f %14.3g\n", name.c_str(), c.fraction, c.maxOverlap,
                c.meanOverlap, c.meanDistance);
}

int runViews(ViewsArgs& a) {
    const profile::PlatformProfile platformProfile = resolveProfile(a.profileArgs);
    const profile::Profile& prof = platformProfile.switches;
    if (!a.profileArgs.profile.empty()) { // the profile's resolution unless given
        if (a.widthOption->count() == 0) a.width = platformProfile.width;
        if (a.heightOption->count() == 0) a.height = platformProfile.height;
    }
    if (a.width < 1 || a.height < 1 || a.width > 16384 || a.height > 16384)
        throw UsageError("--width/--height must be in 1..16384");
    if (!(a.fov > 1.0f && a.fov < 179.0f)) throw UsageError("--fov must be in (1, 179) degrees");
    if (a.worstCase && (!a.view.empty() || !a.camera.empty()))
        throw Error("--worst-case searches a camera: leave out --view and --camera");
    scene::Scene s = loadSceneWithOverrides(a.scene);
    probes::ProbeSet set = readProbesForScene(a.probes, s, a.force);
    // gi.volume_lod: coverage counts only the volumes the renderer would load.
    std::vector<bool> kept(set.volumes.size(), false);
    for (int v : profile::selectVolumes(set, profile::parseVolumeLod(prof.gi.volumeLod)))
        kept[size_t(v)] = true;
    const views::CoverageTester tester(s, set, kept);

    nlohmann::json out{{"scene", s.name},
                       {"probes_file", a.probes},
                       {"width", a.width},
                       {"height", a.height},
                       {"volumes", set.volumes.size()},
                       {"volumes_kept", std::count(kept.begin(), kept.end(), true)}};
    double worst = 1.0; // lowest coverage reported, for --min-coverage
    if (!a.json)
        std::printf("scene %s, %zu triangles; %s: %zu volume(s), %ld kept; %dx%d\n", s.name.c_str(),
                    s.triangleCount(), a.probes.c_str(), set.volumes.size(),
                    long(std::count(kept.begin(), kept.end(), true)), a.width, a.height);
    if (a.worstCase) {
        auto t0 = std::chrono::steady_clock::now();
        if (!a.json) {
            std::fflush(stdout); // the table header first, then the progress line
            std::fprintf(stderr, "searching the worst-case view...\n");
        }
        views::WorstCase wc = views::findWorstCaseView(tester, a.width, a.height, a.fov);
        double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        worst = wc.coverage.fraction;
        out["worst_case"] = viewJson(wc.view, wc.coverage);
        out["worst_case"]["poses_searched"] = wc.candidates;
        out["worst_case"]["seconds"] = sec;
        if (!a.json) {
            std::printf("worst-case view (%d poses searched, %.2f s):\n", wc.candidates, sec);
            std::printf("  %-20s %9s %12s %13s %14s\n", "view", "needs GI", "max overlap",
                        "mean overlap", "mean distance");
            printRow(wc.view.name, wc.coverage);
            std::printf("  --camera %s\n", viewsCameraSpec(wc.view).c_str());
            if (wc.coverage.fraction < 1.0)
                std::printf("  note: %.2f%% of the pixels need no GI (sky or outside every "
                            "volume): no camera found with full coverage\n",
                            100.0 * (1.0 - wc.coverage.fraction));
        }
    } else {
        std::vector<scene::View> list;
        if (!a.view.empty() || !a.camera.empty())
            list.push_back(chooseView(s, a.view, a.camera));
        else
            list = s.views;
        out["views"] = nlohmann::json::array();
        if (!a.json)
            std::printf("  %-20s %9s %12s %13s %14s\n", "view", "needs GI", "max overlap",
                        "mean overlap", "mean distance");
        for (scene::View v : list) {
            if (!a.camera.empty()) v.name = "camera";
            views::Coverage c = tester.measure(v, a.width, a.height);
            worst = std::min(worst, c.fraction);
            out["views"].push_back(viewJson(v, c));
            if (!a.json) printRow(v.name, c);
        }
    }
    if (a.json) writeJson(a.json, out.dump(2) + "\n");
    std::fflush(stdout);
    if (a.minCoverage >= 0 && worst < a.minCoverage) {
        std::fprintf(stderr, "error: coverage %.4f is below --min-coverage %.4f\n", worst,
                     a.minCoverage);
        return 1;
    }
    return 0;
}

const RegisterCommand registerViews{
    {"views", "Fraction of a view's pixels that need GI; find the worst-case view", 45,
     [](CLI::App& cmd) {
         auto a = std::make_shared<ViewsArgs>();
         addSceneOptions(cmd, a->scene);
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--probes", a->probes, "Probe file (probebench bake) giving the volumes")
             ->required();
         cmd.add_flag("--worst-case", a->worstCase,
                      "Search a camera whose every pixel needs GI (the benchmark's default view)");
         cmd.add_option("--view", a->view, "Check one named view (default: all of the scene's)");
         cmd.add_option("--camera", a->camera, "Check a camera px,py,pz,tx,ty,tz[,fovdeg]");
         a->widthOption = cmd.add_option("--width", a->width,
                                         "Image width in pixels (default: the --profile's, "
                                         "else 1280)");
         a->heightOption = cmd.add_option("--height", a->height,
                                          "Image height in pixels (default: the --profile's, "
                                          "else 720)");
         cmd.add_option("--fov", a->fov, "Vertical field of view of the searched camera (degrees)")
             ->capture_default_str();
         addProfileOptions(cmd, a->profileArgs, "gi.volume_lod decides which volumes count.");
         cmd.add_option("--min-coverage", a->minCoverage,
                        "Exit 1 when a reported coverage is below this fraction (e.g. 1.0)");
         a->json.add(cmd, "The views");
         return [a] { return runViews(*a); };
     }}};

} // namespace
} // namespace pb::app
