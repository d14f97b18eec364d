// probebench render: one frame of a scene to PNG (and optionally PFM and GBuffer dumps), or an
// interactive window with --platform glfw. With --probes FILE the frame has DDGI from the baked
// probes, shaped by the profile switches (--set key=value, renderer/profile/SwitchTable.cpp);
// --debug NAME shows a GI debug view, --verbose / --json report the GI pass per volume.
#include "CommandRegistry.h"
#include "bench/report/WindowFrameTimes.h"
#include "JsonOption.h"
#include "OutputPaths.h"
#include "ProbeOptions.h"
#include "FlyCamera.h"
#include "PlatformOptions.h"
#include "ProfileOptions.h"
#include "bench/path/RenderPath.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "frame/GiCoverageView.h"
#include "gl/DebugOutput.h"
#include "image/Image.h"
#include "passes/GiApplyPass.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/VolumeRanksFile.h"
#include "profile/SwitchTable.h"
#include "scene/DefaultView.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace pb::app {
namespace {

struct RenderArgs {
    bool force = false; // --probes baked for another scene
    bool mkdir = false;  // create missing parent folders of the outputs
    SceneArgs scene;
    platform::PlatformOptions platform;
    std::string view;
    std::string camera;
    int width = 1280, height = 720;
    std::string out, outHdr, dumpDir;
    float exposure = 0.0f; // 0 = the scene's
    int frames = 0;        // glfw: frames before closing (0 = until ESC)
    std::string probes, scenario;
    ProfileArgs profileArgs; // --profile, --set
    const CLI::Option *widthOption = nullptr, *heightOption = nullptr;
    bool listSwitches = false;
    std::string debug; // --debug NAME
    JsonOption json;
    bool verbose = false;
    std::string path, outDir, compareTo; // camera path mode (RenderPath.h)
};

int scenarioIndex(const probes::ProbeSet& set, const RenderArgs& a) {
    if (a.scenario.empty()) return 0;
    int i = set.findScenario(a.scenario);
    if (i >= 0) return i;
    std::string names;
    for (const auto& s : set.scenarios)
        names += (names.empty() ? "" : ", ") + s.name;
    throw Error("--scenario: '" + a.scenario + "' is not in " + a.probes + " (" + names + ")");
}

// Refused before anything renders (OutputPaths.h): each output is written as its name says,
// where it says, or the command fails - never silently skipped.
void checkOutputs(const RenderArgs& a) {
    const bool window = a.platform.name == "glfw" && a.out.empty() && a.path.empty();
    for (const auto& [option, value] : {std::pair{"--out-hdr", &a.outHdr},
                                        std::pair{"--dump-gbuffer", &a.dumpDir}}) {
        if (value->empty()) continue;
        if (window)
            throw Error(std::string(option) + ": the window mode writes nothing at exit; add "
                                              "--out to render one frame and write it too");
        if (!a.path.empty())
            throw Error(std::string(option) + ": not written in --path mode (frames are PNGs "
                                              "in --out-dir)");
    }
    if (!a.out.empty()) checkOutputFile("--out", a.out, {".png"}, "an 8-bit sRGB PNG", a.mkdir);
    if (!a.outHdr.empty())
        checkOutputFile("--out-hdr", a.outHdr, {".pfm"}, "a linear HDR PFM", a.mkdir);
    if (!a.dumpDir.empty()) checkOutputFolder("--dump-gbuffer", a.dumpDir, a.mkdir);
}

scene::View chooseRenderView(const scene::Scene& s, const RenderArgs& a) {
    return app::chooseView(s, a.view, a.camera); // SceneOptions: one message, with "did you mean"
}

int runInteractive(platform::Platform& p, render::FrameRenderer& r, const scene::Scene& s,
                   const scene::View& start, int maxFrames) {
    FlyCamera cam(start, s.worldBounds());
    platform::InputState input;
    auto last = std::chrono::steady_clock::now();
    bench::WindowFrameTimes times;
    std::cout << "window open: WASD move, Q/E down/up, Shift faster, drag to look, ESC quits\n";
    for (int frame = 0; maxFrames <= 0 || frame < maxFrames; ++frame) {
        input = {};
        p.pollEvents(input);
        if (input.quit) break;
        auto now = std::chrono::steady_clock::now();
        cam.update(input, std::chrono::duration<double>(now - last).count());
        last = now;
        int w = 0, h = 0;
        p.framebufferSize(w, h);
        if (w <= 0 || h <= 0) continue;
        r.render(render::makeRenderView(cam.view(), s.worldBounds(), w, h));
        r.presentToWindow(w, h);
        p.swapBuffers();
        times.framePresented();
    }
    std::cout << times.summary() << "\n";
    return 0;
}

// What the view sees (scene::checkView), for --verbose, --json and the default view's warning.
std::string viewCheckText(const scene::ViewCheck& c) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "sees %.0f%% geometry from the front, %.0f%% sky, %.0f%% back faces",
                  100.0 * c.frontFraction, 100.0 * c.skyFraction, 100.0 * c.backFraction);
    return buf;
}

nlohmann::json renderJson(const RenderArgs& a, const scene::Scene& s, const scene::View& view,
                          const scene::ViewCheck& check, const platform::Platform& platform,
                          const render::FrameRenderer& r, double ms) {
    auto orNull = [](const std::string& v) {
        return v.empty() ? nlohmann::json(nullptr) : nlohmann::json(v);
    };
    nlohmann::json j;
    j["scene"] = s.name;
    j["view"] = view.name;
    j["camera"] = app::cameraSpec(view); // ready for --camera
    j["view_check"] = {{"front_fraction", check.frontFraction},
                       {"sky_fraction", check.skyFraction},
                       {"back_fraction", check.backFraction},
                       {"inside_closed_mesh", check.insideClosedMesh},
                       {"good", check.good()}};
    j["platform"] = platform.description();
    j["width"] = a.width;
    j["height"] = a.height;
    j["first_frame_ms"] = ms;
    j["out"] = a.out;
    j["out_hdr"] = orNull(a.outHdr);
    j["skipped"] = nlohmann::json::array();
    for (const render::SkippedWork& w : r.skipped())
        j["skipped"].push_back({{"what", w.what}, {"why", w.why}});
    j["gi"] = nullptr;
    if (const render::GpuProbes* gp = r.gpuProbes()) {
        const render::GiApplyPass* pass = r.giApplyPass();
        nlohmann::json& gi = j["gi"];
        gi["volumes_loaded"] = gp->volumes().size();
        gi["scenario"] = gp->scenarioName();
        gi["format"] = probes::formatName(gp->format());
        gi["probe_gpu_bytes"] = gp->bytes();
        gi["target_gpu_bytes"] = pass->targetBytes();
        gi["debug_view"] = orNull(a.debug);
        gi["skipped_this_frame"] = r.giSkippedLastFrame();
        gi["pass"] = r.giSkippedLastFrame() ? nlohmann::json(nullptr)
                                            : render::giPassStatsJson(pass->stats());
    }
    return j;
}

// Every refusal of an option combination, before anything is loaded; returns the --debug
// view. The profile's output resolution applies here, unless --width/--height say otherwise.
render::GiDebugView checkArgs(RenderArgs& a, const profile::PlatformProfile& platformProfile) {
    if (!a.profileArgs.sets.empty() && a.probes.empty())
        throw Error("--set: the GI switches need --probes FILE");
    if (!a.profileArgs.profile.empty() && a.probes.empty())
        throw Error("--profile: the GI switches need --probes FILE");
    if (!a.profileArgs.profile.empty()) {
        if (a.widthOption->count() == 0) a.width = platformProfile.width;
        if (a.heightOption->count() == 0) a.height = platformProfile.height;
    }
    if (!a.scenario.empty() && a.probes.empty()) throw Error("--scenario needs --probes FILE");
    const render::GiDebugView debugView =
        a.debug.empty() ? render::GiDebugView::None : render::parseGiDebugView(a.debug);
    const bool coverage = debugView == render::GiDebugView::VolumeCoverage;
    if (debugView != render::GiDebugView::None && a.probes.empty())
        throw Error("--debug " + a.debug + ": the GI debug views need --probes FILE");
    if (coverage && !a.outHdr.empty())
        throw Error("--out-hdr: --debug volume_coverage is an 8-bit image only");
    if (coverage && a.out.empty())
        throw Error("--debug volume_coverage: needs --out (it is made from a read-back)");
    if (a.json && a.out.empty()) throw Error("--json: needs --out (a rendered frame to report)");
    if (a.width < 1 || a.height < 1 || a.width > 16384 || a.height > 16384)
        throw UsageError("--width/--height must be in 1..16384");
    if (a.path.empty() && !(a.outDir.empty() && a.compareTo.empty()))
        throw Error(std::string(a.outDir.empty() ? "--compare-to" : "--out-dir") +
                    ": needs --path NAME|FILE");
    if (!a.path.empty() && (a.outDir.empty() || !a.out.empty()))
        throw Error("--path: frames go to --out-dir DIR (required; not --out)");
    if (a.out.empty() && a.path.empty() && a.platform.name != "glfw")
        throw Error("--out is required (the PNG to write)");
    checkOutputs(a);
    return debugView;
}

void printGiLine(std::ostream& info, const render::GpuProbes& gp, const probes::ProbeSet& set,
                 const profile::PlatformProfile& platformProfile, render::GiDebugView debugView) {
    std::string changed;
    for (const auto& c : platformProfile.switches.changedSwitches())
        changed += " " + c;
    const bool sh = platformProfile.switches.gi.technique != profile::GiTechnique::Ddgi;
    info << "gi: " << platformProfile.switches.get("gi.technique") << ", " << gp.volumes().size() << " of " << set.volumes.size()
         << " volume(s), scenario '" << gp.scenarioName() << "', "
         << (sh ? "rgba16f sh" : probes::formatName(gp.format())) << ", " << double(gp.bytes()) / (1024.0 * 1024.0)
         << " MiB on the GPU; profile " << platformProfile.name
         << ", switches:" << (changed.empty() ? " defaults" : changed)
         << (debugView == render::GiDebugView::None
                 ? ""
                 : std::string("; debug view ") + render::giDebugViewName(debugView))
         << "\n";
}

// One rendered frame, read back in full before anything is written.
struct RenderedFrame {
    image::Image8 ldr;
    image::ImageF hdr; // only with --out-hdr
    double ms = 0.0;   // the first frame, shader compilation included
};

RenderedFrame renderFrame(const RenderArgs& a, render::FrameRenderer& renderer,
                          const scene::Scene& s, const scene::View& view, gl::DebugOutput& debug,
                          std::uint64_t glMark, bool coverage) {
    RenderedFrame f;
    auto t0 = std::chrono::steady_clock::now();
    renderer.render(render::makeRenderView(view, s.worldBounds(), a.width, a.height));
    glFinish();
    f.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // Read everything back before writing anything: a failure leaves no partial output.
    f.ldr = renderer.readOutput();
    if (coverage) f.ldr = render::giCoverageImage(renderer.giApplyPass()->stats(), f.ldr);
    if (!a.outHdr.empty()) f.hdr = renderer.readRadiance();
    if (auto errors = debug.errorsSince(glMark); !errors.empty())
        throw Error("the GL reported " + std::to_string(errors.size()) +
                    " error(s) while rendering; nothing written:\n" +
                    gl::DebugOutput::format(errors));
    return f;
}

void writeFrame(const RenderArgs& a, render::FrameRenderer& renderer, const RenderedFrame& f) {
    makeParentFolder(a.out);
    image::writePng(a.out, f.ldr);
    if (!a.outHdr.empty()) {
        makeParentFolder(a.outHdr);
        image::writePfm(a.outHdr, f.hdr);
    }
    if (!a.dumpDir.empty()) renderer.dumpGBuffer(a.dumpDir);
}

// What was rendered and written; with --debug volume_coverage the legend, with --verbose the
// GI pass per volume.
void printFrameReport(std::ostream& info, const RenderArgs& a,
                      const render::FrameRenderer& renderer, double ms, bool coverage) {
    const render::GiApplyPass* giPass = renderer.giApplyPass();
    info << "rendered " << a.width << "x" << a.height << " in " << ms
         << " ms (one frame, includes shader compilation"
         << (giPass && giPass->stats().counted && !renderer.giSkippedLastFrame()
                 ? " and per-volume pixel counting"
                 : "")
         << ")\n"
         << "wrote " << a.out << (a.outHdr.empty() ? "" : " and " + a.outHdr)
         << (a.dumpDir.empty() ? "" : ", GBuffer channels in " + a.dumpDir) << "\n";
    if (coverage)
        info << "volume_coverage: left = the volume that shaded each pixel:\n"
             << render::giCoverageLegend(giPass->stats())
             << "right = full evaluations per pixel: 1 blue, 2 green, 3 yellow, 4+ red\n";
    if (giPass && a.verbose) {
        if (renderer.giSkippedLastFrame())
            info << "skipped passes gi-apply" << (renderer.giUpsample() ? ", upsample" : "")
                 << " this frame: none of the " << renderer.gpuProbes()->volumes().size()
                 << " loaded volume(s) is in the view frustum (the lighting took its no-GI "
                    "path; probe textures and GI targets stay allocated)\n";
        else
            info << render::giPassStatsText(giPass->stats());
    }
}

int runRender(RenderArgs& a) {
    const profile::PlatformProfile platformProfile = resolveProfile(a.profileArgs);
    const profile::Profile& prof = platformProfile.switches;
    if (a.listSwitches) {
        std::cout << profile::describeSwitchesText(prof);
        return 0;
    }
    const render::GiDebugView debugView = checkArgs(a, platformProfile);
    const bool coverage = debugView == render::GiDebugView::VolumeCoverage;
    scene::Scene s = loadSceneWithOverrides(a.scene);
    scene::View view = chooseRenderView(s, a);
    // The default view is chosen by what it sees (DefaultView.h); one that still sees badly is
    // said, with its pose as a --camera to start from (issue 42 item 1).
    const bool defaultView = a.view.empty() && a.camera.empty();
    const scene::ViewCheck check =
        defaultView || a.verbose || a.json ? scene::checkView(s, view) : scene::ViewCheck{};
    if (defaultView && !check.good())
        std::cerr << "warning: the default view of '" << s.name << "' " << viewCheckText(check)
                  << (check.insideClosedMesh ? ", from inside a closed mesh" : "")
                  << "; pass --camera or --view (it was --camera " << app::cameraSpec(view) << ")\n";
    probes::ProbeSet probeSet;
    render::GiOptions gi;
    if (!a.probes.empty()) {
        probeSet = readProbesForScene(a.probes, s, a.force);
        requireTechniqueData(a.probes, probeSet, prof);
        gi.probes = &probeSet;
        gi.scenario = scenarioIndex(probeSet, a);
        gi.profile = prof;
        gi.debugView = debugView;
    }
    // Human lines go to stdout, or to stderr when stdout carries the JSON.
    std::ostream& info = a.json ? std::cerr : std::cout;

    a.platform.width = a.width;
    a.platform.height = a.height;
    auto platform = platform::createPlatform(a.platform);
    // Every GL error is a failure: the command exits non-zero and writes nothing.
    gl::DebugOutput debug;
    const std::uint64_t glMark = debug.mark();
    render::FrameSettings settings = render::defaultFrameSettings(s);
    if (a.exposure > 0) settings.exposure = a.exposure;
    if (!a.path.empty())
        return bench::renderPath({&s, view, gi, settings, a.path, a.outDir, a.compareTo, a.frames, a.width,
                           a.height, &debug});
    render::FrameRenderer renderer(s, settings, gi);
    // Counting reads the GPU back after every volume: only when asked for.
    if (renderer.giApplyPass() && (a.verbose || a.json || coverage))
        renderer.giApplyPass()->setCountPixels(true);
    info << "scene " << sceneSummary(s) << "; view '" << view.name << "'\n";
    if (a.verbose)
        info << "view: --camera " << app::cameraSpec(view) << "; " << viewCheckText(check) << "\n";
    info << "platform: " << platform->description() << "\n";
    if (const render::GpuProbes* gp = renderer.gpuProbes())
        printGiLine(info, *gp, probeSet, platformProfile, debugView);
    if (a.verbose)
        for (const render::SkippedWork& w : renderer.skipped())
            info << render::skippedLine(w) << "\n";

    if (platform->isWindowed() && a.out.empty())
        return runInteractive(*platform, renderer, s, view, a.frames);

    const RenderedFrame frame = renderFrame(a, renderer, s, view, debug, glMark, coverage);
    writeFrame(a, renderer, frame);
    printFrameReport(info, a, renderer, frame.ms, coverage);
    if (a.json) writeJson(a.json, renderJson(a, s, view, check, *platform, renderer, frame.ms).dump(2) + "\n");
    if (platform->isWindowed()) return runInteractive(*platform, renderer, s, view, a.frames);
    return 0;
}

const RegisterCommand registerRender{
    {"render", "Render a scene to an image (or a window with --platform glfw)", 20,
     [](CLI::App& cmd) {
         auto a = std::make_shared<RenderArgs>();
         addSceneOptions(cmd, a->scene);
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--view", a->view, "Named view of the scene (default: its first)");
         cmd.add_option("--camera", a->camera,
                        "Camera px,py,pz,tx,ty,tz[,fovdeg] (overrides --view)");
         a->widthOption = cmd.add_option(
             "--width", a->width, "Image width in pixels (default: the --profile's, else 1280)");
         a->heightOption = cmd.add_option(
             "--height", a->height, "Image height in pixels (default: the --profile's, else 720)");
         cmd.add_option("--out", a->out, "PNG to write (8-bit sRGB, tonemapped; name ends in .png)");
         cmd.add_flag("--mkdir", a->mkdir,
                      "Create missing parent folders of --out, --out-hdr, --dump-gbuffer (else "
                      "a missing folder is an error)");
         cmd.add_option("--out-hdr", a->outHdr,
                        "PFM to write (linear HDR radiance before exposure)");
         cmd.add_option("--dump-gbuffer", a->dumpDir, "Folder to write every GBuffer channel to");
         cmd.add_option("--exposure", a->exposure, "Linear exposure scale (default: the scene's)");
         cmd.add_option("--frames", a->frames,
                        "Frames to show or play, not to time: glfw: close the window after N "
                        "frames (0 = on ESC); --path: frames to render (0 = all of it). "
                        "(`bench --frames` is the timed frames per variant per round.)");
         cmd.add_option("--path", a->path,
                        "Play a camera path: static, slow_pan, fast_turn, doorway_walk (rooms) or "
                        "a TOML file; it starts at --view/--camera");
         cmd.add_option("--out-dir", a->outDir, "--path: folder for frame_NNNN.png (and errors.*)");
         cmd.add_option("--compare-to", a->compareTo,
                        "--path: 'full' also renders full-resolution GI per frame and writes "
                        "errors.csv/errors.json (PSNR, FLIP, disocclusion error)");
         cmd.add_option("--probes", a->probes, "Probe file (probebench bake): render with DDGI");
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--scenario", a->scenario,
                        "Lighting scenario of --probes (default: its first)");
         addProfileOptions(cmd, a->profileArgs, "Needs --probes.");
         cmd.add_flag("--list-switches", a->listSwitches, "Print every profile switch and exit");
         cmd.add_option("--debug", a->debug,
                        "GI debug view (needs --probes): gi_only, "
                        "probes_irradiance, probes_visibility, "
                        "volume_coverage (an image twice as wide: shading "
                        "volume | evaluations per pixel)");
         cmd.add_flag("--verbose", a->verbose,
                      "Report the GI pass per volume: how it was drawn, "
                      "pixels evaluated (counting reads back per volume); and one line per "
                      "pass or resource the frame skipped, with why");
         a->json.add(cmd, "The frame's report (counts pixels like --verbose; the human lines go to "
                            "stderr)");
         return [a] { return runRender(*a); };
     }}};

} // namespace
} // namespace pb::app
