// probebench bench: platform profiles against the reference on the same frame (worst-case view
// by default): per-pass times in interleaved rounds, accuracy (FLIP, PSNR, SSIM, relative MSE of
// the GI irradiance), the GI pass's texture-fetch floor, and with --ablate what every switch
// saves and costs. JSON for machines, a self-contained HTML report, a Markdown summary on stdout.
// With --respond, after the timed sessions, each profile's response to a scene change
// (respond's measurement, RespondRun.h) with its switches and [update] budget.
#include "CommandRegistry.h"
#include "DeviceOptions.h"
#include "JsonOption.h"
#include "OutputPaths.h"
#include "PlatformOptions.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "bench/respond/RespondRun.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/report/CiLevels.h"
#include "bench/report/HtmlReport.h"
#include "bench/report/MarkdownSummary.h"
#include "bench/report/ResultJson.h"
#include "bench/runner/BenchContext.h"
#include "bench/runner/BenchTruth.h"
#include "bench/runner/FewerBouncePasses.h"
#include "bench/report/PredictionMeasured.h"
#include "bench/runner/CacheModelRun.h"
#include "bench/runner/PredictionRun.h"
#include "bench/runner/ProbeCache.h"
#include "bench/runner/SectionTimer.h"
#include "bench/runner/SessionRunner.h"
#include "bench/shaders/MesaShim.h"
#include "bench/shaders_gl/TargetWorkers.h"
#include "core/Error.h"
#include "core/MachineState.h"
#include "core/FileIO.h"
#include "frame/FrameRenderer.h"
#include "gl/DebugOutput.h"
#include "metrics/ImageMetrics.h"
#include "passes/GiDebugInjection.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/VolumeRanksFile.h"
#include "views/WorstCaseView.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace pb::app {
namespace {

namespace fs = std::filesystem;

struct BenchArgs {
    bool force = false; // --probes baked for another scene
    SceneArgs scene;
    platform::PlatformOptions platform;
    std::vector<std::string> profiles, sets;
    std::string reference = "reference";
    bool ablate = false, strict = false, noFloor = false, noCacheModel = false;
    bool requireQuiet = false; // refuse to time on a busy machine
    int frames = 3, rounds = 7, warmup = 2, width = 0, height = 0;
    JsonOption json;
    std::string view, camera, probes, volumes = "auto", cacheDir, html, heatmaps,
                                      timing = "auto";
    bool mkdir = false; // create missing parent folders of the outputs
    double ppd = 67.0;
    bool truth = false; // --truth: accuracy against the path-traced ground truth too
    int truthSpp = 64;
    std::vector<std::string> respond; // --respond EVENT (respond's --event); empty: no response
    int respondFrames = 150;
    std::string targets; // --targets: the weak GPUs' compilers (bench/shaders/README.md)
    std::string predict; // --predict: device files for the device model (bench/devicemodel)
    int targetTimeout = 600;
};

void progress(const std::string& line) {
    std::fprintf(stderr, "bench: %s\n", line.c_str());
    std::fflush(stderr);
}

std::string cameraSpec(const scene::View& v) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", v.position.x, v.position.y,
                  v.position.z, v.target.x, v.target.y, v.target.z, v.fovYDegrees);
    return buf;
}

void validate(const BenchArgs& a) {
    if (a.frames < 1 || a.frames > 1000) throw UsageError("--frames must be in 1..1000");
    if (a.rounds < 1 || a.rounds > 1000) throw UsageError("--rounds must be in 1..1000");
    if (a.warmup < 1 || a.warmup > 100)
        throw UsageError("--warmup must be in 1..100 (the first frame compiles shaders)");
    if ((a.width > 0) != (a.height > 0)) throw Error("--width and --height go together");
    if (a.width < 0 || a.height < 0 || a.width > 16384 || a.height > 16384)
        throw UsageError("--width/--height must be in 16..16384");
    if (a.width > 0 && (a.width < 16 || a.height < 16))
        throw UsageError("--width/--height must be in 16..16384");
    if (!a.view.empty() && !a.camera.empty()) throw Error("give --view or --camera, not both");
    if (!(a.ppd > 0)) throw UsageError("--ppd must be positive");
    if (a.truthSpp < 1) throw UsageError("--truth-spp must be at least 1");
    if (a.respondFrames < 2 || a.respondFrames > 10000)
        throw UsageError("--respond-frames must be in 2..10000");
    if (a.targetTimeout < 1) throw UsageError("--target-timeout must be at least 1 s");
    if (!a.predict.empty()) shaders::findMesaShim(); // the model needs the compilers
    if (!a.targets.empty()) {
        // Said before the bake and the timing: names, and whether the compilers are built.
        shaders::parseShaderTargets(a.targets);
        shaders::findMesaShim();
    }
    // Said before bench's own bake (minutes), which stores sparse probes respond cannot update.
    if (!a.respond.empty() && a.probes.empty())
        throw Error("--respond: needs --probes FILE, a dense probe file (bake --dense)");
}

// `bench --respond`: respond's measurement at the bench's --width/--height (respond's 160x90
// without), every check done here, before anything is timed. Null without --respond.
std::unique_ptr<bench::RespondRun> prepareResponse(const BenchArgs& a, const scene::Scene& s,
                                            const probes::ProbeSet& set,
                                            const std::string& probesPath) {
    if (a.respond.empty()) return nullptr;
    bench::RespondSettings rs;
    rs.probesName = probesPath;
    rs.events = a.respond;
    rs.frames = a.respondFrames;
    if (a.width > 0) {
        rs.width = a.width;
        rs.height = a.height;
    }
    rs.cacheDir = a.cacheDir;
    try {
        return std::make_unique<bench::RespondRun>(
            s, set, rs, [](const std::string& line) { progress("respond: " + line); });
    } catch (const Error& e) {
        throw Error(std::string("--respond: ") + e.what());
    }
}

// Per profile (its variant 0: the profile with the run's --set), respond's figures without the
// error curves; profiles that could not run are listed with why.
nlohmann::json measureResponse(bench::RespondRun& run, const BenchArgs& a,
                               const std::vector<bench::SessionResult>& sessions,
                               gl::DebugOutput& debug) {
    nlohmann::json out = {{"events", a.respond}, {"frames", a.respondFrames}};
    nlohmann::json profiles = nlohmann::json::array();
    for (const bench::SessionResult& s : sessions) {
        const profile::PlatformProfile& p = s.session.profile;
        if (!s.profile().ok()) {
            profiles.push_back({{"profile", p.name}, {"not_run", s.profile().error}});
            continue;
        }
        progress("respond: profile " + p.name);
        nlohmann::json j = run.measure(
            {p.name, p.switches, p.updateRaysPerFrame, p.updateUploadBytesPerFrame}, debug);
        // What every profile shares goes to the top once; the rest stays per profile.
        const char* shared[] = {"scene", "probes", "frames", "width",        "height",
                                "view",  "events", "radius", "sample_bakes", "rays_per_update"};
        for (const char* k : shared)
            if (j.contains(k)) {
                out[k] = j[k];
                j.erase(k);
            }
        j.erase("closed_form_hysteresis");
        j.erase("closed_form_max_deviation");
        for (auto& sched : j["schedules"])
            sched.erase("error_curve");
        profiles.push_back(std::move(j));
    }
    out["profiles"] = std::move(profiles);
    return out;
}

// The camera every variant renders: --camera, --view, or the worst-case view (searched at a
// small size of the first session's aspect; every result records its own coverage).
nlohmann::json chooseBenchView(const BenchArgs& a, const scene::Scene& s,
                               const probes::ProbeSet& set, const bench::BenchPlan& plan,
                               scene::View& view) {
    if (!a.camera.empty() || !a.view.empty()) {
        view = chooseView(s, a.view, a.camera);
        if (!a.camera.empty()) view.name = "camera";
        return {{"source", a.camera.empty() ? "view " + view.name : "camera"},
                {"camera", cameraSpec(view)}};
    }
    const bench::Session& first = plan.sessions.front();
    const int h = std::min(first.height, 180);
    const int w = std::max(16, int(double(first.width) * h / first.height + 0.5));
    progress("searching the worst-case view (every pixel needs GI) at " + std::to_string(w) + "x" +
             std::to_string(h));
    const views::WorstCase wc = views::findWorstCaseView(s, set, w, h);
    view = wc.view;
    return {{"source", "worst-case"},
            {"camera", cameraSpec(view)},
            {"search_size", {w, h}},
            {"search_coverage", wc.coverage.fraction},
            {"poses_searched", wc.candidates}};
}

// Heat maps share one scale (the largest FLIP of any profile, at least 0.05) so they compare;
// FLIP errors of GI switches are small, and a 0..1 ramp would show them black.
void writeOutputs(const BenchArgs& a, bench::BenchResult& r,
                  const std::vector<bench::AccuracyPictures>& pictures,
                  const std::vector<bench::TruthMaps>& truthMaps) {
    r.heatmapScale = 0.05;
    for (const auto& s : r.sessions)
        if (s.profile().accuracy.measured)
            r.heatmapScale = std::max(r.heatmapScale, s.profile().accuracy.flipMax);
    std::string dir = a.heatmaps;
    if (dir.empty() && (!a.html.empty() || !a.json.file().empty())) {
        fs::path base(a.html.empty() ? a.json.file() : a.html);
        dir = (base.parent_path() / (base.stem().string() + "-heatmaps")).string();
    }
    if (!dir.empty()) {
        std::error_code ec;
        fs::create_directories(dir, ec);
        if (ec) throw Error("--heatmaps " + dir + ": cannot create the folder");
        for (size_t s = 0; s < r.sessions.size(); ++s) {
            const bench::AccuracyPictures& p = pictures[s];
            if (p.flip.pixels.empty()) continue;
            std::string png =
                (fs::path(dir) / (r.sessions[s].session.profile.name + ".png")).string();
            image::writePng(png, metrics::errorHeatMap(p.flip, float(r.heatmapScale)));
            bench::AccuracyResult& acc = r.sessions[s].variants[0].accuracy;
            acc.heatmapFile = png;
            // Beside it the frames it compares ("-frame"/"-reference" are the truth's names).
            const std::string stem =
                (fs::path(dir) / r.sessions[s].session.profile.name).string();
            acc.frameFile = stem + "-output.png";
            acc.referenceFrameFile = stem + "-reference-output.png";
            image::writePng(acc.frameFile, p.frame);
            image::writePng(acc.referenceFrameFile, p.reference);
        }
        if (!truthMaps.empty()) bench::writeTruthPictures(r.sessions, truthMaps, dir, r.truth);
    }
    if (a.json) writeJson(a.json, bench::benchJson(r).dump(2) + "\n");
    if (!a.html.empty()) {
        std::string text = bench::htmlReport(r);
        writeFileAtomic(a.html, text.data(), text.size());
    }
}

int runBench(const BenchArgs& a) {
    const auto t0 = std::chrono::steady_clock::now();
    validate(a);
    if (a.requireQuiet)
        if (const std::string noisy = noisyMachineNow(); !noisy.empty())
            throw Error("--require-quiet: refusing to time: " + noisy);
    if (const std::string inj = render::giDebugInjectionSummary(); !inj.empty())
        std::fprintf(stderr, "warning: test-only fault injection active: %s\n", inj.c_str());
    const profile::ProfileSearch search = profileSearch();
    profile::PlatformProfile reference = profile::loadProfile(a.reference, search);
    std::vector<profile::PlatformProfile> profiles =
        loadProfilesWithSets(a.profiles, a.sets, search);
    bench::BenchPlan plan =
        bench::makeBenchPlan(profiles, reference, {a.ablate, a.width, a.height});
    const std::vector<devicemodel::DeviceSpec> devices =
        a.predict.empty() ? std::vector<devicemodel::DeviceSpec>{}
                          : resolvePredictDevices(a.predict, profiles);
    for (const char* opt : {"--json", "--html"}) {
        const std::string path = std::string(opt) == "--json" ? a.json.file() : a.html;
        if (!path.empty()) prepareOutputParent(opt, path, a.mkdir);
    }
    if (!a.heatmaps.empty()) checkOutputFolder("--heatmaps", a.heatmaps, a.mkdir);
    scene::Scene s = loadSceneWithOverrides(a.scene);
    std::string probesPath = a.probes;
    int bakedPasses = 0; // the bench's probes' bounce passes when baked here (0: unknown)
    probes::ProbeSet set =
        a.probes.empty()
            ? bench::benchProbes(s, a.volumes,
                                 a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir,
                                 &probesPath, progress, &bakedPasses)
            : readProbesForScene(a.probes, s, a.force);
    const std::unique_ptr<bench::RespondRun> respond = prepareResponse(a, s, set, probesPath);

    bench::BenchResult result;
    scene::View view;
    result.view = chooseBenchView(a, s, set, plan, view);
    if (!a.targets.empty()) {
        ShaderRunInputs in;
        in.targets = a.targets;
        in.plan = {a.profiles, a.reference, a.sets, a.ablate};
        in.scene = a.scene;
        in.probesPath = probesPath;
        in.camera = cameraSpec(view);
        in.timeoutSeconds = a.targetTimeout;
        progress("compiling every variant's programs on the targets " + a.targets);
        result.shaderTargets = runShaderTargets(
            in, s.name, [](const std::string& line) { progress("targets: " + line); });
    }
    shaders::ShaderStatisticsRun modelStats; // the device model's compilers, twins included
    if (!devices.empty())
        modelStats = runModelCompilers(
            devices, {a.profiles, a.reference, a.sets, a.ablate}, a.scene, probesPath,
            cameraSpec(view), a.targetTimeout, s.name,
            [](const std::string& line) { progress("device model: " + line); });
    auto platform = platform::createPlatform(timingPlatform(a.platform));
    gl::DebugOutput debug;
    const gl::GlCaps caps = gl::queryCaps();
    const bench::TimingChoice timing =
        bench::chooseTiming(a.timing, caps, gl::detectDriverQuirks());
    result.context = bench::benchContext(*platform, caps);
    result.scene = {{"name", s.name},
                    {"summary", sceneSummary(s)},
                    {"probes_file", probesPath},
                    {"probe_volumes", set.volumes.size()},
                    {"probes", set.probeCount()},
                    {"probe_format", probes::formatName(set.format())}};
    result.settings = {a.frames, a.rounds, a.warmup, a.ablate, timing.name, timing.reason, a.ppd};
    // Said once everything is checked, before the minutes of measuring, and again in every
    // table's header and the summary.
    if (const std::string w = bench::roundsWarning(a.rounds); !w.empty())
        std::cerr << "warning: " << w << "\n";
    progress(std::to_string(plan.sessions.size()) + " profile(s), " +
             std::to_string(plan.variantCount()) + " variant(s), " + std::to_string(a.rounds) +
             " rounds x " + std::to_string(a.frames) + " frames; timing " + timing.name + " on " +
             caps.renderer);

    bench::RunnerOptions o;
    o.frames = a.frames;
    o.rounds = a.rounds;
    o.warmup = a.warmup;
    o.timing = timing;
    o.es = caps.es;
    o.fetchFloor = !a.noFloor;
    o.pixelsPerDegree = a.ppd;
    o.progress = progress;
    bench::RunnerInputs in{&s, &set, view, render::defaultFrameSettings(s), &debug};
    bench::TruthBySize truths;
    bench::FewerBouncePasses fewerPasses;
    bench::TruthBySize directTruths;
    scene::Scene directScene;
    if (a.truth) {
        const std::string cacheDir = a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir;
        truths = bench::computeBenchTruth(s, view, plan, {a.truthSpp, 32, cacheDir, progress}, &result.truth);
        in.truth = &truths;
        if (bench::hasDirectLight(s)) {
            directScene = bench::directLightScene(s);
            directTruths = bench::computeBenchDirectTruth(directScene, view, plan,
                                                          {a.truthSpp, 1, cacheDir, progress},
                                                          &result.truth["direct_light"]);
            in.directTruth = &directTruths;
            in.directScene = &directScene;
        } else {
            result.truth["direct_light"] = {{"why_not", "no sun and no punctual light: the "
                                                        "rasterizer draws no direct light"}};
        }
        fewerPasses = bench::bakeOneFewerBouncePass(s, set, bakedPasses, progress);
        result.truth["fewer_bounce_passes"] = bench::fewerBouncePassesJson(fewerPasses);
        if (fewerPasses.set) in.fewerPassProbes = &*fewerPasses.set;
        else progress("note: no reference with one bounce pass fewer: " + fewerPasses.why);
    }
    std::vector<bench::AccuracyPictures> pictures;
    std::vector<bench::TruthMaps> truthMaps;
    result.sessions = bench::runBenchPlan(plan, in, o, &pictures, a.truth ? &truthMaps : nullptr);
    if (!a.noCacheModel) result.cacheModel = bench::cacheModelEntries(plan, s, set, view, progress);
    if (!devices.empty()) {
        bench::PredictionRequest req{devices, a.predict == "own", true, progress};
        result.predictions = bench::predictDevices(plan, s, set, view, modelStats, req);
        bench::attachMeasured(result.predictions, result.sessions);
    }
    if (respond) result.response = measureResponse(*respond, a, result.sessions, debug);
    result.context["load_average_end"] = bench::loadAverage();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::vector<std::string> skipped;
    for (const auto& session : result.sessions)
        for (const auto& v : session.variants)
            if (!v.ok()) skipped.push_back(v.variant.id + ": " + v.error);
    for (const std::string& p : shaders::shaderRunProblems(result.shaderTargets))
        skipped.push_back("--targets " + p);
    for (const bench::DevicePrediction& d : result.predictions)
        if (!d.error.empty()) skipped.push_back("--predict " + d.device + ": " + d.error);
    if (a.strict && !skipped.empty())
        throw Error("--strict: " + std::to_string(skipped.size()) +
                    " variant(s) could not run, nothing written; first: " + skipped.front());
    writeOutputs(a, result, pictures, truthMaps);
    std::cout << bench::markdownSummary(result);
    // One warning per distinct reason, naming the variants it hit.
    std::vector<std::pair<std::string, std::string>> reasons; // reason, variant ids
    for (const auto& session : result.sessions)
        for (const auto& v : session.variants) {
            if (v.ok()) continue;
            auto it = std::find_if(reasons.begin(), reasons.end(),
                                   [&](const auto& r) { return r.first == v.error; });
            if (it == reasons.end())
                reasons.emplace_back(v.error, v.variant.id);
            else if ((", " + it->second + ",").find(", " + v.variant.id + ",") == std::string::npos)
                it->second += ", " + v.variant.id;
        }
    for (const auto& [why, ids] : reasons)
        std::fprintf(stderr, "warning: not run (%s): %s\n", why.c_str(), ids.c_str());
    for (const std::string& p : shaders::shaderRunProblems(result.shaderTargets))
        std::fprintf(stderr, "warning: --targets %s\n", p.c_str());
    for (const bench::DevicePrediction& d : result.predictions) {
        if (!d.error.empty())
            std::fprintf(stderr, "warning: --predict %s: %s\n", d.device.c_str(), d.error.c_str());
        for (const bench::PredictedSession& ps : d.sessions)
            if (ps.overBudget())
                std::fprintf(stderr, "warning: model: %s: %s predicted %.2f ms, over its %.1f ms budget\n",
                             d.device.c_str(), ps.profile.c_str(), ps.budgetFrameMs(), ps.budgetMs);
    }
    if (!a.json.file().empty()) std::cout << "\nwrote " << a.json.file() << "\n";
    if (!a.html.empty())
        std::cout << (a.json.file().empty() ? "\n" : "") << "wrote " << a.html << "\n";
    return 0;
}

const RegisterCommand registerBench{
    {"bench",
     "Benchmark platform profiles against the reference: per-pass times, accuracy, ablation, "
     "report",
     50, [](CLI::App& cmd) {
         auto a = std::make_shared<BenchArgs>();
         addSceneOptions(cmd, a->scene);
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--profiles,--profile", a->profiles,
                        "Profiles to measure, comma-separated names or .toml files (--profile: "
                        "the same; default: "
                        "every profile `probebench profiles` lists)")
             ->delimiter(',');
         cmd.add_option("--reference", a->reference,
                        "The accuracy baseline profile (rendered at each profile's size)")
             ->capture_default_str();
         cmd.add_option("--set", a->sets,
                        "Switch key=value applied to every measured profile, not to the "
                        "reference (repeatable)");
         cmd.add_flag("--ablate", a->ablate,
                      "Per switch where a profile differs from the reference: the profile with "
                      "only that switch reverted, and the reference with only that switch applied");
         cmd.add_option("--frames", a->frames,
                        "Timed frames per variant per round (each round times this many "
                        "after the warm-up). (`render --frames` is frames to show or play.)")
             ->capture_default_str();
         cmd.add_option("--rounds", a->rounds,
                        "Interleaved rounds (A B A B ...): the deltas' intervals come from them; "
                        "6 or more give 95%, fewer a lower level (printed with each table, "
                        "and warned about)")
             ->capture_default_str();
         cmd.add_option("--warmup", a->warmup,
                        "Frames per variant before timing (never counted; the first compiles "
                        "shaders)")
             ->capture_default_str();
         cmd.add_option("--width", a->width,
                        "Render every profile at this width instead of its own output size");
         cmd.add_option("--height", a->height, "...and this height");
         cmd.add_option("--view", a->view, "A named view of the scene instead of the worst case");
         cmd.add_option("--camera", a->camera,
                        "Camera px,py,pz,tx,ty,tz[,fovdeg] instead of the worst case");
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--probes", a->probes,
                        "Probe file (probebench bake); default: bake --volumes once and cache it");
         cmd.add_option("--volumes", a->volumes,
                        "Without --probes: the volumes to bake, auto (stored sparse), "
                        "auto-uniform or a volumes file (bench/volumes/rooms_nested.toml nests a "
                        "volume per room); the probes are what 'bake --volumes V " +
                            bench::benchBakeFlags() +
                            "' writes, byte for byte, cached in --cache-dir")
             ->capture_default_str();
         cmd.add_option("--cache-dir", a->cacheDir,
                        "Folder of the baked-probe cache (default: ~/.cache/probebench)");
         cmd.add_flag("--mkdir", a->mkdir,
                      "Create missing parent folders of --json, --html, --heatmaps (else a "
                      "missing folder is an error, before any work)");
         a->json.add(cmd, "The full result");
         cmd.add_option("--html", a->html, "Write the self-contained HTML report to this file");
         cmd.add_option("--heatmaps", a->heatmaps,
                        "Folder for the FLIP heat-map PNGs (default: <json/html name>-heatmaps/)");
         cmd.add_option("--timing", a->timing,
                        "auto (timer queries where the driver's are trustworthy, else the CPU "
                        "clock around glFinish), cpu, cpu-time (process CPU time around glFinish: "
                        "steadier on a shared machine), or query")
             ->check(CLI::IsMember(bench::timingRequestNames()))
             ->capture_default_str();
         cmd.add_flag("--no-floor", a->noFloor, "Skip the GI pass's texture-fetch floor");
         cmd.add_flag("--no-cache-model", a->noCacheModel,
                      "Skip the report's texture-cache model (GL-free; minutes at 1440p)");
         cmd.add_option("--ppd", a->ppd, "FLIP viewing condition, pixels per degree")
             ->capture_default_str();
         cmd.add_flag("--truth", a->truth,
                      "Also measure every profile and ablation row (and the reference) against the "
                      "path-traced ground truth of the view (probebench truth; cached)");
         cmd.add_option("--truth-spp", a->truthSpp, "Samples per pixel of that truth")
             ->capture_default_str();
         cmd.add_option("--respond", a->respond,
                        "After the timed sessions, per profile: how many frames the GI takes to "
                        "follow this scene change (respond's --event syntax, e.g. sun:off@10; "
                        "repeatable), with the profile's switches and [update] budget, at "
                        "--width/--height or 160x90; needs a dense --probes file");
         cmd.add_option("--respond-frames", a->respondFrames,
                        "Frames of that response run (as respond's --frames)")
             ->capture_default_str();
         cmd.add_option("--targets", a->targets,
                        "Also compile every variant's programs with these weak GPUs' own "
                        "compilers (probebench shaders --list-targets; all) and report their "
                        "statistics beside the timings; needs scripts/mesa-shim.sh");
         cmd.add_option("--predict", a->predict,
                        "Also predict every profile's frame, passes and switch deltas on these "
                        "devices with the device model (probebench devices; NAME[,NAME...], all, "
                        "or own: each profile on the device its [budget] model names), beside the "
                        "measured ones; needs scripts/mesa-shim.sh");
         cmd.add_option("--target-timeout", a->targetTimeout,
                        "Seconds one target's compiler run may take")
             ->capture_default_str();
         cmd.add_flag("--require-quiet", a->requireQuiet,
                      "Refuse to time (exit 1) when the machine is busy before the run: load "
                      "average or other processes' CPU use above half the CPUs, or more than 5% "
                      "of the CPU time stolen by the host");
         cmd.add_flag("--strict", a->strict,
                      "Fail (writing nothing) when any variant cannot run, instead of reporting "
                      "it as not run");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runBench(*a);
         };
     }}};

} // namespace
} // namespace pb::app
