#pragma once
// Runs a BenchPlan on the current GL context: per session, every variant's renderer is built
// (a variant the renderer rejects - a switch value not implemented, a format the driver lacks
// - is recorded as unsupported, not fatal), warmed up (the first frames compile shaders and
// are never counted), then timed in interleaved rounds: round r renders `frames` frames of
// every variant, the order rotated by r, so every paired delta sees the same load. The GI
// fetch floor follows each profile/reference variant's frames. Accuracy, coverage and GI memory
// are taken after the timing (AccuracyCapture.h).
#include "AccuracyCapture.h"
#include "SectionTimer.h"
#include "TruthAccuracyCapture.h"
#include "bench/report/AblationPlan.h"
#include "bench/report/BenchResult.h"
#include "gl/DebugOutput.h"
#include "image/Image.h"
#include "passes/FrameContext.h"
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <functional>
#include <string>

namespace pb::bench {

struct RunnerOptions {
    int frames = 3, rounds = 7, warmup = 2;
    TimingChoice timing;
    bool es = true; // GL ES context (timer-query entry points)
    bool fetchFloor = true;
    double pixelsPerDegree = 67.0;
    std::function<void(const std::string&)> progress; // one line each; may be empty
};

struct RunnerInputs {
    const scene::Scene* scene = nullptr;
    const probes::ProbeSet* probes = nullptr;
    scene::View view;
    render::FrameSettings settings;
    gl::DebugOutput* debug = nullptr; // GL errors fail the variant that caused them
    // `bench --truth`: the ground truth at every session's size; null = no truth accuracy.
    const TruthBySize* truth = nullptr;
    // With `truth`: the probes with one bounce pass fewer (FewerBouncePasses.h); the reference
    // variant renders with them too, into SessionResult::referenceFewerPassesVsTruth.
    const probes::ProbeSet* fewerPassProbes = nullptr;
    // With `truth`: the direct-light truth (BenchTruth.h computeBenchDirectTruth) of
    // `directScene`; the frame without GI of that scene against it goes to
    // SessionResult::directLightVsTruth.
    const TruthBySize* directTruth = nullptr;
    const scene::Scene* directScene = nullptr;
};

// `pictures` (optional) receives, parallel to the sessions, the profile variant's per-pixel
// FLIP map against the reference and both frames (empty when not measured), for the report; `truthMaps`
// (optional, with in.truth) the pictures against the truth (TruthAccuracyCapture.h).
std::vector<SessionResult> runBenchPlan(const BenchPlan& plan, const RunnerInputs& in,
                                        const RunnerOptions& o,
                                        std::vector<AccuracyPictures>* pictures = nullptr,
                                        std::vector<TruthMaps>* truthMaps = nullptr);

} // namespace pb::bench
