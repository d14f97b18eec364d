// probebench respond: how fast the GI follows a scene change under each probe update schedule,
// and what the speed costs (issue 20). Every frame of the run renders the worst-case view with
// the probes as the update engine (renderer/respond) leaves them; the updated probes' tiles
// are re-uploaded as sub-rectangles (passes/ProbeTileUpload.h). Each schedule is measured
// against the converged result of the changed scene (its full re-bake, cached).
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "PlatformOptions.h"
#include "ProbeOptions.h"
#include "ProfileOptions.h"
#include "RespondReport.h"
#include "SceneOptions.h"
#include "bench/runner/ProbeCache.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "frame/FrameRenderer.h"
#include "gl/DebugOutput.h"
#include "image/Image.h"
#include "passes/ProbeTileUpload.h"
#include "probes/ProbeLayout.h"
#include "probes/StorageFormat.h"
#include "respond/ProbeUpdate.h"
#include "respond/ResponseMetrics.h"
#include "respond/SampleBakes.h"
#include "views/WorstCaseView.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace pb::app {
namespace {

using namespace pb::respond;

struct RespondArgs {
    SceneArgs scene;
    platform::PlatformOptions platform;
    std::string probes, scenario, timeline, schedules = "hysteresis,rtxgi,hastened";
    std::vector<std::string> events;
    int frames = 150, raysPerFrame = 0, raysPerUpdate = 256, sampleBakes = 16;
    long long uploadBytesPerFrame = 0; // 0: no limit
    ProfileArgs profileArgs;           // --profile: switches and its [update] budget
    const CLI::Option *raysOption = nullptr, *bytesOption = nullptr;
    int width = 160, height = 90;
    float radius = 1.5f;
    bool force = false;
    std::string outDir, cacheDir; // empty: the probe cache's default folder
    JsonOption json;
};

void progress(const std::string& line) {
    std::cerr << "respond: " << line << "\n";
}

// One world per effective event, in frame order: what the scene is from that frame on.
struct Step {
    ResponseEvent event;
    World world; // after the event
    Change change;
    bool effective = true; // the bake's inputs changed
    int samples = -1;      // index into the sample bakes (one per distinct world), -1: none
};

LumaImage luma(const image::ImageF& img) {
    LumaImage y(std::size_t(img.width) * std::size_t(img.height));
    for (std::size_t i = 0; i < y.size(); ++i) {
        const float* p = &img.pixels[i * std::size_t(img.channels)];
        y[i] = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    }
    return y;
}

void syncStored(probes::ProbeSet& set, int scenario) {
    // A fresh GPU copy (after an event rebuilds the renderer) reads `stored`.
    for (probes::ProbeTexture& t : set.irradiance[std::size_t(scenario)])
        probes::quantise(t, set.format());
}

struct ScheduleRun {
    Schedule schedule;
    std::vector<double> error; // relative to response frame 0
    std::vector<LumaImage> frames;
    std::size_t updates = 0, bytes = 0, responseFrames = 0;
    double blendMs = 0;
    std::vector<image::Image8> ldr; // every frame, with --out-dir
};

class Run {
public:
    explicit Run(RespondArgs& a) : a_(a) {}
    int go();

private:
    void prepare();
    LumaImage renderReference();
    std::vector<bool> farPixels() const;
    ScheduleRun runSchedule(Schedule s);
    nlohmann::json figures(const ScheduleRun& r) const;
    std::unique_ptr<render::FrameRenderer> makeRenderer(const World& w,
                                                        const probes::ProbeSet& set) const;
    image::ImageF renderFrame(render::FrameRenderer& r);

    RespondArgs& a_;
    World initial_;
    probes::ProbeSet set_, reference_;
    int scenario_ = 0;
    std::vector<Step> steps_;
    std::vector<std::unique_ptr<SampleBakes>> samples_;
    scene::View view_;
    render::FrameSettings settings_;
    profile::Profile profile_;
    std::string profileName_;
    std::unique_ptr<gl::DebugOutput> debug_;
    std::uint64_t glMark_ = 0;
    int lastEventFrame_ = 0;
    int budget_ = 0; // probe updates per frame, 0: every marked probe
};

void Run::prepare() {
    if (a_.frames < 2) throw Error("--frames: must be at least 2");
    if (a_.width < 8 || a_.height < 8) throw Error("--width/--height: at least 8 pixels");
    if (a_.sampleBakes < 1) throw Error("--sample-bakes: must be at least 1");
    if (!(a_.radius > 0.0f)) throw Error("--radius: must be positive");
    // A profile's update budget applies unless the command line gives one.
    const profile::PlatformProfile platformProfile = resolveProfile(a_.profileArgs);
    profileName_ = platformProfile.name;
    profile_ = platformProfile.switches;
    if (!a_.raysOption->count()) a_.raysPerFrame = platformProfile.updateRaysPerFrame;
    if (!a_.bytesOption->count())
        a_.uploadBytesPerFrame = platformProfile.updateUploadBytesPerFrame;
    if (a_.raysPerFrame < 0) throw Error("--rays-per-frame: must not be negative");
    if (a_.uploadBytesPerFrame < 0) throw Error("--upload-bytes-per-frame: must not be negative");
    std::vector<Schedule> schedules = parseSchedules(a_.schedules, "--schedule");
    (void)schedules;
    std::vector<ResponseEvent> events;
    for (const std::string& e : a_.events)
        events.push_back(parseEvent(e));
    if (!a_.timeline.empty())
        for (ResponseEvent& e : readTimeline(a_.timeline))
            events.push_back(std::move(e));
    if (events.empty()) throw Error("--event: no event given (e.g. --event sun:off@10)");
    std::stable_sort(events.begin(), events.end(),
                     [](const auto& x, const auto& y) { return x.frame < y.frame; });

    initial_.scene = loadSceneWithOverrides(a_.scene);
    set_ = readProbesForScene(a_.probes, initial_.scene, a_.force);
    if (!a_.scenario.empty()) {
        scenario_ = set_.findScenario(a_.scenario);
        if (scenario_ < 0) throw Error("--scenario: '" + a_.scenario + "' is not in " + a_.probes);
    }
    if (set_.format() == probes::StorageFormat::Bc6h)
        throw Error(a_.probes + ": respond updates rgba16f or rgba32f probe files, not bc6h");
    for (const auto& vs : set_.states)
        for (const auto& s : vs)
            if (!s.stored)
                throw Error(a_.probes + ": respond needs a dense probe file (bake --dense)");
    initial_.scenario = set_.scenarios[std::size_t(scenario_)];
    initial_.scene.sun = initial_.scenario.sun;
    initial_.scene.sky = initial_.scenario.sky;

    // Every event is checked before anything is traced or rendered.
    World w = initial_;
    for (const ResponseEvent& e : events) {
        checkEvent(e, w, a_.frames);
        Step s;
        s.event = e;
        World before = w;
        s.change = applyEvent(e, w, initial_);
        s.world = w;
        s.effective = bakeInputsDiffer(before, w, set_);
        steps_.push_back(std::move(s));
    }
    lastEventFrame_ = steps_.back().event.frame;

    progress("searching the worst-case view at " + std::to_string(a_.width) + "x" +
             std::to_string(a_.height));
    view_ = views::findWorstCaseView(initial_.scene, set_, a_.width, a_.height).view;
    for (Step& s : steps_) {
        if (!s.effective) continue;
        samples_.push_back(std::make_unique<SampleBakes>(s.world, set_, a_.raysPerUpdate,
                                                         a_.sampleBakes, progress));
        s.samples = int(samples_.size()) - 1;
    }
    std::string note;
    progress("converged reference: full re-bake of the changed scene");
    reference_ =
        convergedBake(steps_.back().world, set_,
                      a_.cacheDir.empty() ? bench::defaultProbeCacheDir() : a_.cacheDir, &note);
    progress("converged reference " + note);
    // The budget in probe updates: what the rays buy and what the upload allows (one 8x8
    // tile per update), the smaller; at least one update per frame.
    if (!samples_.empty() && a_.raysPerFrame > 0)
        budget_ = std::max(1, int(double(a_.raysPerFrame) / samples_.back()->raysPerUpdate()));
    if (a_.uploadBytesPerFrame > 0) {
        const long long tileBytes = probes::kIrradianceTile * probes::kIrradianceTile *
                                    (set_.format() == probes::StorageFormat::Rgba16f ? 8 : 16);
        const int byBytes = int(std::max(1LL, a_.uploadBytesPerFrame / tileBytes));
        budget_ = budget_ > 0 ? std::min(budget_, byBytes) : byBytes;
    }
    settings_ = render::defaultFrameSettings(initial_.scene);
}

std::unique_ptr<render::FrameRenderer> Run::makeRenderer(const World& w,
                                                         const probes::ProbeSet& set) const {
    render::GiOptions gi;
    gi.probes = &set;
    gi.scenario = &set == &reference_ ? 0 : scenario_;
    gi.profile = profile_;
    return std::make_unique<render::FrameRenderer>(w.scene, settings_, gi);
}

image::ImageF Run::renderFrame(render::FrameRenderer& r) {
    r.render(render::makeRenderView(view_, initial_.scene.worldBounds(), a_.width, a_.height));
    image::ImageF img = r.readRadiance();
    if (auto errors = debug_->errorsSince(glMark_); !errors.empty())
        throw Error("the GL reported " + std::to_string(errors.size()) +
                    " error(s) while rendering; nothing written:\n" +
                    gl::DebugOutput::format(errors));
    return img;
}

LumaImage Run::renderReference() {
    auto r = makeRenderer(steps_.back().world, reference_);
    return luma(renderFrame(*r));
}

// Pixels whose surface lies beyond --radius of every local change point (none when any
// change is global): light there should not move.
std::vector<bool> Run::farPixels() const {
    const std::size_t n = std::size_t(a_.width) * std::size_t(a_.height);
    std::vector<bool> far(n, false);
    std::vector<glm::vec3> points;
    for (const Step& s : steps_) {
        if (s.change.global && s.effective) return far;
        points.insert(points.end(), s.change.points.begin(), s.change.points.end());
    }
    const views::CoverageTester tester(steps_.back().world.scene, reference_);
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < a_.height; ++y)
        for (int x = 0; x < a_.width; ++x)
            pixels.push_back({x, y});
    const auto surface = tester.surfacePoints(view_, a_.width, a_.height, pixels);
    for (std::size_t i = 0; i < n; ++i) {
        if (!surface[i].hit) continue;
        bool beyond = true;
        for (const glm::vec3& p : points)
            beyond = beyond && glm::length(surface[i].position - p) > a_.radius;
        far[i] = beyond;
    }
    return far;
}

ScheduleRun Run::runSchedule(Schedule schedule) {
    ScheduleRun out;
    out.schedule = schedule;
    probes::ProbeSet set = set_;
    ProbeUpdater updater(set, scenario_, schedule);
    World world = initial_;
    auto renderer = makeRenderer(world, set);
    std::size_t nextStep = 0;
    int samplesIndex = -1;
    const std::string name = scheduleName(schedule);
    for (int f = 0; f < a_.frames; ++f) {
        bool changed = false;
        while (nextStep < steps_.size() && steps_[nextStep].event.frame == f) {
            const Step& s = steps_[nextStep++];
            world = s.world;
            updater.mark(s.change, a_.radius, s.effective);
            if (s.samples >= 0) samplesIndex = s.samples;
            changed = true;
        }
        if (changed) {
            syncStored(set, scenario_);
            renderer = makeRenderer(world, set);
        }
        if (f == lastEventFrame_) // response frame 0: the changed scene, no update yet
            out.frames.push_back(luma(renderFrame(*renderer)));
        if (samplesIndex >= 0) {
            const SampleBakes& sb = *samples_[std::size_t(samplesIndex)];
            const auto t0 = std::chrono::steady_clock::now();
            const std::vector<ProbeRef> updated = updater.step(
                budget_, [&](const ProbeRef& p, int k, float* rgb) { sb.sample(p, k, rgb); });
            std::vector<render::ProbeTile> tiles;
            for (const ProbeRef& p : updated)
                tiles.push_back({p.volume, p.probe});
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            const std::size_t bytes =
                render::uploadProbeTiles(*renderer->gpuProbes(), set, scenario_, tiles);
            if (f >= lastEventFrame_) {
                out.updates += updated.size();
                out.bytes += bytes;
                out.blendMs += ms;
                ++out.responseFrames;
            }
        }
        image::ImageF img = renderFrame(*renderer);
        if (f >= lastEventFrame_) out.frames.push_back(luma(img));
        // Kept in memory and written only once every schedule ran: no partial output.
        if (!a_.outDir.empty()) out.ldr.push_back(renderer->readOutput());
        if (f % 25 == 0)
            progress(name + ": frame " + std::to_string(f) + "/" + std::to_string(a_.frames));
    }
    return out;
}

nlohmann::json nullIfNever(int frame) {
    return frame < 0 ? nlohmann::json() : nlohmann::json(frame);
}

int Run::go() {
    prepare();
    auto platform = platform::createPlatform([&] {
        auto p = a_.platform;
        p.width = a_.width;
        p.height = a_.height;
        return p;
    }());
    debug_ = std::make_unique<gl::DebugOutput>();
    glMark_ = debug_->mark();
    const LumaImage ref = renderReference();
    const std::vector<bool> far = farPixels();
    double refMean = 0;
    for (float y : ref)
        refMean += y;
    refMean /= double(std::max<std::size_t>(ref.size(), 1));
    nlohmann::json result = {{"scene", initial_.scene.name},
                             {"probes", a_.probes},
                             {"width", a_.width},
                             {"height", a_.height},
                             {"frames", a_.frames},
                             {"view", view_.name},
                             {"radius", a_.radius},
                             {"rays_per_update_requested", a_.raysPerUpdate},
                             {"probe_updates_per_frame_budget", budget_},
                             {"sample_bakes", a_.sampleBakes},
                             {"reference_mean_luminance", refMean},
                             {"profile", profileName_},
                             {"rays_per_frame_budget", a_.raysPerFrame},
                             {"upload_bytes_per_frame_budget", a_.uploadBytesPerFrame}};
    result["events"] = nlohmann::json::array();
    for (const Step& s : steps_)
        result["events"].push_back(s.event.spec + (s.effective ? "" : " (no effect)"));
    result["schedules"] = nlohmann::json::array();
    std::vector<std::pair<std::string, std::vector<image::Image8>>> pngs;
    const SampleBakes* sb = samples_.empty() ? nullptr : samples_.back().get();
    for (Schedule s : parseSchedules(a_.schedules, "--schedule")) {
        progress(std::string("schedule ") + scheduleName(s));
        ScheduleRun r = runSchedule(s);
        const double e0 = meanAbsError(r.frames.front(), ref);
        for (const LumaImage& f : r.frames)
            r.error.push_back(e0 > 0 ? meanAbsError(f, ref) / e0 : 0.0);
        const FarDrift drift = farDrift(r.frames, far);
        const double frames = double(std::max<std::size_t>(r.responseFrames, 1));
        const double updatesPerFrame = double(r.updates) / frames;
        nlohmann::json j = {
            {"schedule", scheduleName(s)},
            {"t95_frames", nullIfNever(settleFrame(r.error, 0.05))},
            {"t99_frames", nullIfNever(settleFrame(r.error, 0.01))},
            {"overshoot", overshoot(r.frames, ref)},
            {"flicker", flicker(r.frames, 30)},
            {"far_drift", drift.pixels ? nlohmann::json(drift.drift) : nlohmann::json()},
            {"far_pixels", drift.pixels},
            {"step_error", e0},
            {"final_error", r.error.back()},
            {"probe_updates_per_frame", updatesPerFrame},
            {"rays_per_frame", sb ? updatesPerFrame * sb->raysPerUpdate() : 0.0},
            {"cpu_ms_per_frame",
             (r.blendMs + (sb ? double(r.updates) * sb->cpuMsPerUpdate() : 0.0)) / frames},
            {"blend_ms_per_frame", r.blendMs / frames},
            {"bytes_uploaded", r.bytes},
            {"upload_bytes_per_frame", double(r.bytes) / frames},
            {"error_curve", r.error}};
        result["schedules"].push_back(j);
        pngs.emplace_back(scheduleName(s), std::move(r.ldr));
        if (s == Schedule::Hysteresis) {
            nlohmann::json closed = nlohmann::json::array();
            double worst = 0;
            for (std::size_t n = 0; n < r.error.size(); ++n) {
                const double c = hysteresisResidual({}, int(n));
                closed.push_back(c);
                worst = std::max(worst, std::fabs(r.error[n] - c));
            }
            result["closed_form_hysteresis"] = closed;
            result["closed_form_max_deviation"] =
                budget_ == 0 ? nlohmann::json(worst) : nlohmann::json();
        }
        progress(std::string(scheduleName(s)) + ": t95 " + j["t95_frames"].dump() + ", t99 " +
                 j["t99_frames"].dump() + " frames, final error " + std::to_string(r.error.back()));
    }
    if (sb) {
        result["rays_per_update"] = sb->raysPerUpdate();
        result["cpu_ms_per_update"] = sb->cpuMsPerUpdate();
    }
    if (!a_.outDir.empty()) {
        std::filesystem::create_directories(std::filesystem::path(a_.outDir) / "frames");
        for (const auto& [name, images] : pngs)
            for (std::size_t f = 0; f < images.size(); ++f) {
                char file[64];
                std::snprintf(file, sizeof file, "%s_%04zu.png", name.c_str(), f);
                image::writePng((std::filesystem::path(a_.outDir) / "frames" / file).string(),
                                images[f]);
            }
        const std::string html = respondReportHtml(result);
        writeFileAtomic((std::filesystem::path(a_.outDir) / "report.html").string(), html.data(),
                        html.size());
    }
    if (a_.json) writeJson(a_.json, result.dump(2) + "\n");
    return 0;
}

const RegisterCommand reg{
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
         cmd.add_option("--scenario", a->scenario,
                        "Lighting scenario of --probes (default: its first)");
         cmd.add_option("--event", a->events, "A scene change, e.g. sun:off@10 (see below)");
         cmd.add_option("--timeline", a->timeline, "TOML file of [[event]] spec = \"...\"");
         cmd.add_option("--frames", a->frames, "Frames to run (default 150)");
         cmd.add_option("--schedule", a->schedules,
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
         cmd.add_option("--rays-per-update", a->raysPerUpdate,
                        "Rays per probe and bounce pass of one update's sample (default 256)");
         cmd.add_option("--sample-bakes", a->sampleBakes,
                        "Independent sample bakes the updates cycle through (default 16)");
         cmd.add_option("--radius", a->radius,
                        "Radius of a local change, scene units (default 1.5)");
         cmd.add_option("--width", a->width, "Image width (default 160)");
         cmd.add_option("--height", a->height, "Image height (default 90)");
         cmd.add_option("--out-dir", a->outDir, "Folder for frames/*.png and report.html");
         cmd.add_option("--cache-dir", a->cacheDir,
                        "Where the converged re-bake is cached (default: the probe cache folder, "
                        "as bench and truth use)");
         a->json.add(cmd, "schedules[] with t95_frames, t99_frames, overshoot, flicker, far_drift, "
                          "rays_per_frame, cpu_ms_per_frame, bytes_uploaded, error_curve");
         return [a] {
             Run run(*a);
             return run.go();
         };
     }}};

} // namespace
} // namespace pb::app
