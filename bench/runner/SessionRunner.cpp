#include "SessionRunner.h"

#include "AccuracyCapture.h"
#include "FetchFloorPass.h"
#include "core/MachineState.h"
#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "truth/PathTracer.h"
#include "passes/GiApplyPass.h"

#include <algorithm>
#include <map>
#include <memory>

namespace pb::bench {

namespace {

struct LiveVariant {
    std::unique_ptr<render::FrameRenderer> renderer;
    std::unique_ptr<FetchFloorPass> floor;
    std::vector<std::string> order;                   // section names, first seen first
    std::map<std::string, std::vector<double>> times; // per section, per frame
    std::vector<double> floorTimes;
};

std::string glErrorText(gl::DebugOutput* debug, std::uint64_t mark) {
    if (!debug) return "";
    auto errors = debug->errorsSince(mark);
    if (errors.empty()) return "";
    return "the GL reported " + std::to_string(errors.size()) + " error(s): " + errors.front().text;
}

void fail(VariantResult& v, LiveVariant& live, const std::string& why) {
    v.status = "unsupported";
    v.error = why;
    live.floor.reset();
    live.renderer.reset();
}

// One measured frame (re-taken when timer queries report a disjoint event).
void timedFrame(LiveVariant& live, VariantResult& v, SectionTimer& timer,
                const render::RenderView& rv) {
    for (int attempt = 0; attempt < 3; ++attempt) {
        timer.beginFrame();
        live.renderer->render(rv, &timer);
        if (!timer.endFrame()) continue;
        // A section missing from this frame counts 0 (keeps every series one value per frame).
        for (const auto& [name, ms] : timer.sections())
            if (!live.times.count(name)) {
                live.order.push_back(name);
                live.times[name].assign(v.frameSamples.size(), 0.0);
            }
        for (auto& [name, series] : live.times) {
            double ms = 0;
            for (const auto& [n, t] : timer.sections())
                if (n == name) ms = t;
            series.push_back(ms);
        }
        v.frameSamples.push_back(timer.frameMs());
        return;
    }
    throw Error("timer queries reported disjoint GPU time 3 times in a row; use --timing cpu");
}

void timedFloor(LiveVariant& live, SectionTimer& timer, const render::RenderView& rv) {
    for (int attempt = 0; attempt < 3; ++attempt) {
        timer.beginFrame();
        timer.begin("gi-fetch-floor");
        live.floor->execute(*live.renderer, rv);
        timer.end("gi-fetch-floor");
        if (!timer.endFrame()) continue;
        live.floorTimes.push_back(timer.sections().front().second);
        return;
    }
}

// One frame with the GI pass counting its evaluations (GiPassStats), right after a camera cut
// as the accuracy frame: for the ratio to the fetch floor per evaluation (ResultJson.h).
void countEvaluations(VariantResult& v, LiveVariant& live, const render::RenderView& rv) {
    render::GiApplyPass* gi = live.renderer->giApplyPass();
    if (!gi) return;
    live.renderer->resetGiHistory();
    gi->setCountPixels(true);
    live.renderer->render(rv);
    gi->setCountPixels(false);
    const render::GiPassStats& s = gi->stats();
    v.giEvaluations = s.totalEvaluations();
    v.giTexels = std::int64_t(s.width) * s.height;
}

void summarizeVariant(VariantResult& v, const LiveVariant& live) {
    if (!v.ok() || v.frameSamples.empty()) return;
    v.frameMs = stats::summarize(v.frameSamples);
    for (const std::string& name : live.order) {
        SectionTiming t{name, live.times.at(name), {}};
        t.ms = stats::summarize(t.samples);
        v.sections.push_back(std::move(t));
    }
    if (!live.floorTimes.empty()) {
        SectionTiming f{"gi-fetch-floor", live.floorTimes, stats::summarize(live.floorTimes)};
        v.fetchFloor = f;
    }
}

// The distinct variants of every session of one frame size (equal switches are one variant),
// timed in the same interleaved rounds: each session's reference, profile and ablation rows
// then come from the same rounds as every other session's, so no figure compares two moments
// of a shared machine. `slots[s][i]`: session s's variant i as an index into `unique`.
struct SizeGroup {
    int width = 0, height = 0;
    std::vector<size_t> sessions; // indices into the plan
    std::vector<Variant> unique;
    std::vector<std::vector<size_t>> slots;
};

std::vector<SizeGroup> groupBySize(const BenchPlan& plan) {
    std::vector<SizeGroup> groups;
    for (size_t s = 0; s < plan.sessions.size(); ++s) {
        const Session& session = plan.sessions[s];
        auto g = std::find_if(groups.begin(), groups.end(), [&](const SizeGroup& x) {
            return x.width == session.width && x.height == session.height;
        });
        if (g == groups.end()) {
            SizeGroup fresh;
            fresh.width = session.width;
            fresh.height = session.height;
            g = groups.insert(groups.end(), std::move(fresh));
        }
        g->sessions.push_back(s);
        std::vector<size_t> slots;
        for (const Variant& v : session.variants) {
            auto u = std::find_if(g->unique.begin(), g->unique.end(),
                                  [&](const Variant& x) { return x.switches == v.switches; });
            if (u == g->unique.end()) u = g->unique.insert(g->unique.end(), v);
            // Profile and reference variants get the fetch floor: keep the most telling role.
            if (v.role == VariantRole::Profile || v.role == VariantRole::Reference)
                if (u->role != VariantRole::Profile && u->role != VariantRole::Reference)
                    u->role = v.role;
            slots.push_back(size_t(u - g->unique.begin()));
        }
        g->slots.push_back(std::move(slots));
    }
    return groups;
}

// Builds and warms up every variant of a group (a variant the renderer rejects is recorded as
// unsupported), then times them in interleaved rounds: round r renders every variant in turn,
// the order rotated by r, and per variant first one frame after the switch to it - untimed
// for the statistics, its time kept apart as the cost of switching - then `frames` timed
// frames of the steady state.
void timeGroup(const SizeGroup& g, const RunnerInputs& in, const RunnerOptions& o,
               const std::string& tag, std::vector<LiveVariant>& live,
               std::vector<VariantResult>& results, const render::RenderView& rv) {
    auto say = [&](const std::string& line) {
        if (o.progress) o.progress(tag + " " + line);
    };
    const size_t n = g.unique.size();
    live.resize(n);
    results.resize(n);
    say("building " + std::to_string(n) + " variant(s), " + std::to_string(o.warmup) +
        " warm-up frame(s) each");
    for (size_t i = 0; i < n; ++i) {
        VariantResult& v = results[i];
        v.variant = g.unique[i];
        const std::uint64_t mark = in.debug ? in.debug->mark() : 0;
        try {
            render::GiOptions gi{in.probes, 0, v.variant.switches};
            live[i].renderer = std::make_unique<render::FrameRenderer>(*in.scene, in.settings, gi);
            const bool main =
                v.variant.role == VariantRole::Profile || v.variant.role == VariantRole::Reference;
            if (o.fetchFloor && main)
                live[i].floor = std::make_unique<FetchFloorPass>(v.variant.switches);
            for (int w = 0; w < o.warmup; ++w) {
                live[i].renderer->render(rv);
                if (live[i].floor) live[i].floor->execute(*live[i].renderer, rv);
            }
            glFinish();
        } catch (const Error& e) {
            fail(v, live[i], e.what());
            say("variant '" + v.variant.id + "' not run: " + e.what());
            continue;
        }
        if (std::string why = glErrorText(in.debug, mark); !why.empty()) fail(v, live[i], why);
    }
    SectionTimer timer(o.timing, o.es);
    for (int r = 0; r < o.rounds; ++r) {
        say("round " + std::to_string(r + 1) + "/" + std::to_string(o.rounds));
        for (size_t k = 0; k < n; ++k) {
            const size_t i = (k + size_t(r)) % n;
            VariantResult& v = results[i];
            if (!v.ok()) continue;
            const std::uint64_t mark = in.debug ? in.debug->mark() : 0;
            timer.beginFrame(); // the switch frame: the first after another variant's
            live[i].renderer->render(rv, &timer);
            if (timer.endFrame()) v.switchFrameSamples.push_back(timer.frameMs());
            const size_t first = v.frameSamples.size();
            for (int f = 0; f < o.frames; ++f)
                timedFrame(live[i], v, timer, rv);
            std::vector<double> round(v.frameSamples.begin() + long(first), v.frameSamples.end());
            v.roundMedians.push_back(stats::summarize(round).median);
            if (live[i].floor)
                for (int f = 0; f < o.frames; ++f)
                    timedFloor(live[i], timer, rv);
            if (std::string why = glErrorText(in.debug, mark); !why.empty()) fail(v, live[i], why);
        }
    }
    for (size_t i = 0; i < n; ++i) {
        summarizeVariant(results[i], live[i]);
        if (results[i].ok() && live[i].floor) countEvaluations(results[i], live[i], rv);
    }
}

// One frame of a renderer built for the purpose (the first after a cut, as every variant's
// accuracy frame) against a truth; a GL error on the way is the bench's failure, named `what`.
TruthAccuracy extraFrameAccuracy(const scene::Scene& scene, const render::FrameSettings& settings,
                                 const render::GiOptions& gi, const RunnerInputs& in,
                                 const render::RenderView& rv, const image::ImageF& truthHdr,
                                 double pixelsPerDegree, const std::string& what) {
    const std::uint64_t mark = in.debug ? in.debug->mark() : 0;
    render::FrameRenderer renderer(scene, settings, gi);
    renderer.render(rv);
    const TruthAccuracy a = truthAccuracyOf(
        renderer, truthHdr, truth::tonemap(truthHdr, settings.exposure), pixelsPerDegree);
    if (std::string why = glErrorText(in.debug, mark); !why.empty())
        throw Error("bench --truth: " + what + ": " + why);
    return a;
}

// The reference variant rendered with the probes of one bounce pass fewer.
TruthAccuracy fewerPassAccuracy(const Variant& reference, const RunnerInputs& in,
                                const render::RenderView& rv, const image::ImageF& truthHdr,
                                double pixelsPerDegree) {
    return extraFrameAccuracy(*in.scene, in.settings,
                              render::GiOptions{in.fewerPassProbes, 0, reference.switches}, in, rv,
                              truthHdr, pixelsPerDegree, "the reference with one bounce pass fewer");
}

// The frame without GI of the direct-light scene (sun and punctual lights only) against its
// traced direct light: the rasterizer's own error, under every probe set's.
TruthAccuracy directLightAccuracy(const RunnerInputs& in, const render::RenderView& rv,
                                  const image::ImageF& directTruth, double pixelsPerDegree) {
    render::FrameSettings settings = in.settings; // the frame's exposure, no sky ambient
    settings.ambientUp = settings.ambientDown = glm::vec3(0.0f);
    return extraFrameAccuracy(*in.directScene, settings, render::GiOptions{}, in, rv, directTruth,
                              pixelsPerDegree, "the direct-light frame");
}

// One session's result from its group's timed variants: its own variants (ids, labels, roles)
// with the shared measurements, then accuracy against its reference and its deltas.
SessionResult finishSession(const Session& session, const std::vector<size_t>& slots,
                            const std::vector<LiveVariant>& live,
                            const std::vector<VariantResult>& timed, const RunnerInputs& in,
                            const RunnerOptions& o, const std::string& tag,
                            const render::RenderView& rv, AccuracyPictures* pictures,
                            TruthMaps* truthMaps) {
    if (o.progress)
        o.progress(tag + " accuracy against " +
                   session.variants[size_t(session.referenceVariant)].id);
    SessionResult out;
    out.session = session;
    const size_t n = session.variants.size();
    out.variants.resize(n);
    std::vector<render::FrameRenderer*> renderers(n, nullptr);
    for (size_t i = 0; i < n; ++i) {
        out.variants[i] = timed[slots[i]];
        out.variants[i].variant = session.variants[i];
        if (!out.variants[i].ok()) continue;
        renderers[i] = live[slots[i]].renderer.get();
    }
    // Accuracy is read from a frame right after a camera cut: on the bench's still camera a
    // temporal upsample would otherwise have converged to full resolution and look free. The
    // first frame after a cut is its worst case (= bilateral); its error under motion is what
    // `probebench render --path ... --compare-to full` measures (bench/README.md).
    for (size_t i = 0; i < n; ++i) {
        if (!renderers[i]) continue;
        renderers[i]->resetGiHistory();
        renderers[i]->render(rv);
    }
    AccuracyInputs ai{in.scene,
                      in.probes,
                      in.view,
                      in.settings,
                      session.width,
                      session.height,
                      1, // the irradiance renderer's first frame: also right after a cut
                      o.pixelsPerDegree};
    captureAccuracy(out, renderers, ai, pictures);
    if (in.truth) {
        auto it = in.truth->find({session.width, session.height});
        if (it == in.truth->end())
            throw Error("bench --truth: no truth computed at " + std::to_string(session.width) + "x" +
                        std::to_string(session.height));
        captureTruthAccuracy(out, renderers, it->second, in.settings.exposure, o.pixelsPerDegree,
                             truthMaps);
        if (in.fewerPassProbes && out.reference().ok())
            out.referenceFewerPassesVsTruth =
                fewerPassAccuracy(out.reference().variant, in, rv, it->second, o.pixelsPerDegree);
        if (in.directTruth && in.directScene) {
            auto direct = in.directTruth->find({session.width, session.height});
            if (direct == in.directTruth->end())
                throw Error("bench --truth: no direct-light truth computed at " +
                            std::to_string(session.width) + "x" + std::to_string(session.height));
            out.directLightVsTruth = directLightAccuracy(in, rv, direct->second, o.pixelsPerDegree);
        }
    }
    pairDeltas(out);
    return out;
}

} // namespace

std::vector<SessionResult> runBenchPlan(const BenchPlan& plan, const RunnerInputs& in,
                                        const RunnerOptions& o,
                                        std::vector<AccuracyPictures>* pictures,
                                        std::vector<TruthMaps>* truthMaps) {
    if (o.frames < 1 || o.rounds < 1 || o.warmup < 1)
        throw Error("--frames, --rounds and --warmup must be at least 1 (the first frame "
                    "compiles shaders and is never counted)");
    std::vector<SessionResult> out(plan.sessions.size());
    if (pictures) pictures->assign(plan.sessions.size(), {});
    if (truthMaps) truthMaps->assign(plan.sessions.size(), {});
    const std::vector<SizeGroup> groups = groupBySize(plan);
    for (size_t gi = 0; gi < groups.size(); ++gi) {
        const SizeGroup& g = groups[gi];
        std::string names;
        for (size_t s : g.sessions)
            names += (names.empty() ? "" : ", ") + plan.sessions[s].profile.name;
        const std::string tag = "[" + std::to_string(gi + 1) + "/" +
                                std::to_string(groups.size()) + "] " + std::to_string(g.width) +
                                "x" + std::to_string(g.height) + " (" + names + "):";
        const render::RenderView rv =
            render::makeRenderView(in.view, in.scene->worldBounds(), g.width, g.height);
        std::vector<LiveVariant> live;
        std::vector<VariantResult> timed;
        MachineState before = sampleMachineState();
        timeGroup(g, in, o, tag, live, timed, rv);
        MachineState after = sampleMachineState();
        for (size_t k = 0; k < g.sessions.size(); ++k) {
            const size_t s = g.sessions[k];
            out[s] = finishSession(plan.sessions[s], g.slots[k], live, timed, in, o, tag, rv,
                                   pictures ? &(*pictures)[s] : nullptr,
                                   truthMaps ? &(*truthMaps)[s] : nullptr);
            out[s].machineBefore = before;
            out[s].machineAfter = after;
        }
    }
    return out;
}

} // namespace pb::bench
