// The respond measurement shared by `probebench respond` and `bench --respond` (RespondRun.h).
// Every frame of a run renders the worst-case view with the probes as the update engine leaves
// them; the updated probes' tiles are re-uploaded as sub-rectangles (passes/ProbeTileUpload.h).
#include "RespondRun.h"

#include "bench/runner/ProbeCache.h"
#include "core/Error.h"
#include "core/Luminance.h"
#include "frame/FrameRenderer.h"
#include "gl/DebugOutput.h"
#include "passes/ProbeTileUpload.h"
#include "probes/ProbeLayout.h"
#include "probes/StorageFormat.h"
#include "respond/ProbeUpdate.h"
#include "respond/ResponseMetrics.h"
#include "respond/SampleBakes.h"
#include "views/WorstCaseView.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pb::bench {

using namespace pb::respond;

namespace {

// One world per event, in frame order: what the scene is from that frame on.
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
        y[i] = pb::luminance(p);
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
    std::vector<image::Image8> ldr; // every frame, with keepFrames
};

nlohmann::json nullIfNever(int frame) {
    return frame < 0 ? nlohmann::json() : nlohmann::json(frame);
}

} // namespace

struct RespondRun::Impl {
    RespondSettings a;
    std::function<void(const std::string&)> progress;
    World initial;
    probes::ProbeSet set, reference;
    int scenario = 0;
    std::vector<Step> steps;
    std::vector<std::unique_ptr<SampleBakes>> samples;
    scene::View view;
    render::FrameSettings settings;
    bool prepared = false; // view, sample bakes and reference done
    int lastEventFrame = 0;
    // Per measurement:
    profile::Profile profile;
    gl::DebugOutput* debug = nullptr;
    std::uint64_t glMark = 0;
    int budget = 0; // probe updates per frame, 0: every marked probe

    void check();
    void prepare();
    int updateBudget(const RespondBudget& b) const;
    std::unique_ptr<render::FrameRenderer> makeRenderer(const World& w,
                                                        const probes::ProbeSet& s) const;
    image::ImageF renderFrame(render::FrameRenderer& r);
    std::vector<bool> farPixels() const;
    ScheduleRun runSchedule(Schedule s);
};

void RespondRun::Impl::check() {
    if (a.frames < 2) throw Error("--frames: must be at least 2");
    if (a.width < 8 || a.height < 8) throw Error("--width/--height: at least 8 pixels");
    if (a.sampleBakes < 1) throw Error("--sample-bakes: must be at least 1");
    if (a.raysPerUpdate < 1) throw Error("--rays-per-update: must be at least 1");
    if (!(a.radius > 0.0f)) throw Error("--radius: must be positive");
    (void)parseSchedules(a.schedules, "--schedule");
    std::vector<ResponseEvent> events;
    for (const std::string& e : a.events)
        events.push_back(parseEvent(e));
    if (!a.timeline.empty())
        for (ResponseEvent& e : readTimeline(a.timeline))
            events.push_back(std::move(e));
    if (events.empty()) throw Error("--event: no event given (e.g. --event sun:off@10)");
    std::stable_sort(events.begin(), events.end(),
                     [](const auto& x, const auto& y) { return x.frame < y.frame; });

    if (!a.scenario.empty()) {
        scenario = set.findScenario(a.scenario);
        if (scenario < 0) throw Error("--scenario: '" + a.scenario + "' is not in " + a.probesName);
    }
    if (set.format() == probes::StorageFormat::Bc6h)
        throw Error(a.probesName + ": respond updates rgba16f or rgba32f probe files, not bc6h");
    for (const auto& vs : set.states)
        for (const auto& s : vs)
            if (!s.stored)
                throw Error(a.probesName + ": respond needs a dense probe file (bake --dense)");
    initial.scenario = set.scenarios[std::size_t(scenario)];
    initial.scene.sun = initial.scenario.sun;
    initial.scene.sky = initial.scenario.sky;

    // Every event is checked before anything is traced or rendered.
    World w = initial;
    for (const ResponseEvent& e : events) {
        checkEvent(e, w, a.frames);
        Step s;
        s.event = e;
        World before = w;
        s.change = applyEvent(e, w, initial);
        s.world = w;
        s.effective = bakeInputsDiffer(before, w, set);
        steps.push_back(std::move(s));
    }
    lastEventFrame = steps.back().event.frame;
    settings = render::defaultFrameSettings(initial.scene);
}

void RespondRun::Impl::prepare() {
    progress("searching the worst-case view at " + std::to_string(a.width) + "x" +
             std::to_string(a.height));
    view = views::findWorstCaseView(initial.scene, set, a.width, a.height).view;
    for (Step& s : steps) {
        if (!s.effective) continue;
        samples.push_back(
            std::make_unique<SampleBakes>(s.world, set, a.raysPerUpdate, a.sampleBakes, progress));
        s.samples = int(samples.size()) - 1;
    }
    std::string note;
    progress("converged reference: full re-bake of the changed scene");
    reference =
        convergedBake(steps.back().world, set,
                      a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir, &note);
    progress("converged reference " + note);
    prepared = true;
}

// The budget in probe updates: what the rays buy and what the upload allows (one 8x8 tile per
// update), the smaller; at least one update per frame.
int RespondRun::Impl::updateBudget(const RespondBudget& b) const {
    int n = 0;
    if (!samples.empty() && b.raysPerFrame > 0)
        n = std::max(1, int(double(b.raysPerFrame) / samples.back()->raysPerUpdate()));
    if (b.uploadBytesPerFrame > 0) {
        const long long tileBytes = probes::kIrradianceTile * probes::kIrradianceTile *
                                    (set.format() == probes::StorageFormat::Rgba16f ? 8 : 16);
        const int byBytes = int(std::max(1LL, b.uploadBytesPerFrame / tileBytes));
        n = n > 0 ? std::min(n, byBytes) : byBytes;
    }
    return n;
}

std::unique_ptr<render::FrameRenderer>
RespondRun::Impl::makeRenderer(const World& w, const probes::ProbeSet& s) const {
    render::GiOptions gi;
    gi.probes = &s;
    gi.scenario = &s == &reference ? 0 : scenario;
    gi.profile = profile;
    return std::make_unique<render::FrameRenderer>(w.scene, settings, gi);
}

image::ImageF RespondRun::Impl::renderFrame(render::FrameRenderer& r) {
    r.render(render::makeRenderView(view, initial.scene.worldBounds(), a.width, a.height));
    image::ImageF img = r.readRadiance();
    if (auto errors = debug->errorsSince(glMark); !errors.empty())
        throw Error("the GL reported " + std::to_string(errors.size()) +
                    " error(s) while rendering; nothing written:\n" +
                    gl::DebugOutput::format(errors));
    return img;
}

// Pixels whose surface lies beyond the radius of every local change point (none when any
// change is global): light there should not move.
std::vector<bool> RespondRun::Impl::farPixels() const {
    const std::size_t n = std::size_t(a.width) * std::size_t(a.height);
    std::vector<bool> far(n, false);
    std::vector<glm::vec3> points;
    for (const Step& s : steps) {
        if (s.change.global && s.effective) return far;
        points.insert(points.end(), s.change.points.begin(), s.change.points.end());
    }
    const views::CoverageTester tester(steps.back().world.scene, reference);
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            pixels.push_back({x, y});
    const auto surface = tester.surfacePoints(view, a.width, a.height, pixels);
    for (std::size_t i = 0; i < n; ++i) {
        if (!surface[i].hit) continue;
        bool beyond = true;
        for (const glm::vec3& p : points)
            beyond = beyond && glm::length(surface[i].position - p) > a.radius;
        far[i] = beyond;
    }
    return far;
}

ScheduleRun RespondRun::Impl::runSchedule(Schedule schedule) {
    ScheduleRun out;
    out.schedule = schedule;
    probes::ProbeSet live = set;
    ProbeUpdater updater(live, scenario, schedule);
    World world = initial;
    auto renderer = makeRenderer(world, live);
    std::size_t nextStep = 0;
    int samplesIndex = -1;
    const std::string name = scheduleName(schedule);
    for (int f = 0; f < a.frames; ++f) {
        bool changed = false;
        while (nextStep < steps.size() && steps[nextStep].event.frame == f) {
            const Step& s = steps[nextStep++];
            world = s.world;
            updater.mark(s.change, a.radius, s.effective);
            if (s.samples >= 0) samplesIndex = s.samples;
            changed = true;
        }
        if (changed) {
            syncStored(live, scenario);
            renderer = makeRenderer(world, live);
        }
        if (f == lastEventFrame) // response frame 0: the changed scene, no update yet
            out.frames.push_back(luma(renderFrame(*renderer)));
        if (samplesIndex >= 0) {
            const SampleBakes& sb = *samples[std::size_t(samplesIndex)];
            const auto t0 = std::chrono::steady_clock::now();
            const std::vector<ProbeRef> updated = updater.step(
                budget, [&](const ProbeRef& p, int k, float* rgb) { sb.sample(p, k, rgb); });
            std::vector<render::ProbeTile> tiles;
            for (const ProbeRef& p : updated)
                tiles.push_back({p.volume, p.probe});
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            const std::size_t bytes =
                render::uploadProbeTiles(*renderer->gpuProbes(), live, scenario, tiles);
            if (f >= lastEventFrame) {
                out.updates += updated.size();
                out.bytes += bytes;
                out.blendMs += ms;
                ++out.responseFrames;
            }
        }
        image::ImageF img = renderFrame(*renderer);
        if (f >= lastEventFrame) out.frames.push_back(luma(img));
        // Kept in memory and written by the caller once every schedule ran: no partial output.
        if (a.keepFrames) out.ldr.push_back(renderer->readOutput());
        if (f % 25 == 0)
            progress(name + ": frame " + std::to_string(f) + "/" + std::to_string(a.frames));
    }
    return out;
}

RespondRun::RespondRun(scene::Scene scene, probes::ProbeSet set, RespondSettings settings,
                       std::function<void(const std::string&)> progress)
    : impl_(std::make_unique<Impl>()) {
    impl_->a = std::move(settings);
    impl_->progress = std::move(progress);
    impl_->initial.scene = std::move(scene);
    impl_->set = std::move(set);
    impl_->check();
}

RespondRun::~RespondRun() = default;

nlohmann::json RespondRun::measure(const RespondBudget& budget, gl::DebugOutput& debug,
                                   RespondFrames* frames) {
    Impl& m = *impl_;
    if (budget.raysPerFrame < 0) throw Error("--rays-per-frame: must not be negative");
    if (budget.uploadBytesPerFrame < 0)
        throw Error("--upload-bytes-per-frame: must not be negative");
    if (!m.prepared) m.prepare();
    m.profile = budget.switches;
    m.debug = &debug;
    m.glMark = debug.mark();
    m.budget = m.updateBudget(budget);
    const LumaImage ref = [&] {
        auto r = m.makeRenderer(m.steps.back().world, m.reference);
        return luma(m.renderFrame(*r));
    }();
    const std::vector<bool> far = m.farPixels();
    double refMean = 0;
    for (float y : ref)
        refMean += y;
    refMean /= double(std::max<std::size_t>(ref.size(), 1));
    nlohmann::json result = {{"scene", m.initial.scene.name},
                             {"probes", m.a.probesName},
                             {"width", m.a.width},
                             {"height", m.a.height},
                             {"frames", m.a.frames},
                             {"view", m.view.name},
                             {"radius", m.a.radius},
                             {"rays_per_update_requested", m.a.raysPerUpdate},
                             {"probe_updates_per_frame_budget", m.budget},
                             {"sample_bakes", m.a.sampleBakes},
                             {"reference_mean_luminance", refMean},
                             {"profile", budget.profileName},
                             {"rays_per_frame_budget", budget.raysPerFrame},
                             {"upload_bytes_per_frame_budget", budget.uploadBytesPerFrame}};
    result["events"] = nlohmann::json::array();
    for (const Step& s : m.steps)
        result["events"].push_back(s.event.spec + (s.effective ? "" : " (no effect)"));
    result["schedules"] = nlohmann::json::array();
    const SampleBakes* sb = m.samples.empty() ? nullptr : m.samples.back().get();
    for (Schedule s : parseSchedules(m.a.schedules, "--schedule")) {
        m.progress(std::string("schedule ") + scheduleName(s));
        ScheduleRun r = m.runSchedule(s);
        const double e0 = meanAbsError(r.frames.front(), ref);
        for (const LumaImage& f : r.frames)
            r.error.push_back(e0 > 0 ? meanAbsError(f, ref) / e0 : 0.0);
        const FarDrift drift = farDrift(r.frames, far);
        const double n = double(std::max<std::size_t>(r.responseFrames, 1));
        const double updatesPerFrame = double(r.updates) / n;
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
             (r.blendMs + (sb ? double(r.updates) * sb->cpuMsPerUpdate() : 0.0)) / n},
            {"blend_ms_per_frame", r.blendMs / n},
            {"bytes_uploaded", r.bytes},
            {"upload_bytes_per_frame", double(r.bytes) / n},
            {"error_curve", r.error}};
        result["schedules"].push_back(j);
        if (frames) frames->emplace_back(scheduleName(s), std::move(r.ldr));
        if (s == Schedule::Hysteresis) {
            nlohmann::json closed = nlohmann::json::array();
            double worst = 0;
            for (std::size_t k = 0; k < r.error.size(); ++k) {
                const double c = hysteresisResidual({}, int(k));
                closed.push_back(c);
                worst = std::max(worst, std::fabs(r.error[k] - c));
            }
            result["closed_form_hysteresis"] = closed;
            result["closed_form_max_deviation"] =
                m.budget == 0 ? nlohmann::json(worst) : nlohmann::json();
        }
        m.progress(std::string(scheduleName(s)) + ": t95 " + j["t95_frames"].dump() + ", t99 " +
                   j["t99_frames"].dump() + " frames, final error " +
                   std::to_string(r.error.back()));
    }
    if (sb) {
        result["rays_per_update"] = sb->raysPerUpdate();
        result["cpu_ms_per_update"] = sb->cpuMsPerUpdate();
    }
    return result;
}

} // namespace pb::bench
