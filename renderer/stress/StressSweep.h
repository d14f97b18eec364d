#pragma once
// The stress sweep: every case rendered with every variant, measured against the reference
// variant, and for each broken run the switch that broke it and the guard that fixes it.
// GL-free: rendering goes through StressRenderer (stress/gl/GlStressRenderer.h on a GL
// context; the unit tests use a fake), so the analysis is tested without a GPU.
//
// Per case: the reference frame (referenceVariant(), or the case's truth scene), then each
// variant twice - as given, and with every guard off (RunGuards). A run is broken when its
// frame has a non-finite pixel or its median relative error passes the threshold. For a
// broken run:
//   culprits: base = the reference with the run's guard values. If base is broken too, no
//     switch is to blame ("no switch: the reference breaks too"). Otherwise each differing
//     non-guard key applied alone to base; those that break it are the culprits. If none does
//     alone, each reverted alone in the run; those whose revert fixes it. Else "combination".
//   fixed_by: each guard the run has off, turned on alone; those that fix it. Else "all guards
//     together" when that fixes it. finite_with: for a NaN/Inf run, the guards that alone
//     leave no NaN/Inf pixel (the run may still be wrong for another reason).
// Frames with identical settings are rendered once per case (cache by settings key).
#include "image/Image.h"
#include "stress/StressCases.h"
#include "stress/StressMetrics.h"
#include "stress/StressVariant.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::stress {

struct RenderedFrame {
    image::ImageF radiance;             // linear, un-scaled by any pre-exposure
    image::Image8 output;               // the tonemapped 8-bit image
    std::int64_t nonfiniteGiTexels = 0; // the GI evaluation target
};

class StressRenderer {
public:
    virtual ~StressRenderer() = default;
    // Throws pb::Error (or any std::exception) when the frame cannot be made.
    virtual RenderedFrame render(const CaseData& data, const StressVariant& variant) = 0;
};

enum class RunGuards { AsGiven, Off, Both };

struct SweepOptions {
    std::vector<StressVariant> variants;
    RunGuards guards = RunGuards::Both;
    BreakThresholds thresholds;
    bool analyse = true; // name culprits and guards (extra frames for broken runs)
    // Called with the reference frame ("reference") and each run's frame ("fp16", "fp16/off")
    // of every case, e.g. to write images; analysis frames are not passed.
    std::function<void(const std::string& caseName, const std::string& run,
                       const RenderedFrame& frame)>
        onFrame;
};

struct StressRun {
    std::string caseName, variant;
    bool guardsOff = false; // every guard off (else as the variant gives them)
    Measurement m;
    std::string symptom;
    std::vector<std::string> culprits; // "key=value" or a phrase in parentheses
    std::vector<std::string> fixedBy;  // "gi.guard_x=on" or "(all guards together)"
    // NaN/Inf runs: guards that alone leave no NaN/Inf pixel, even where another cause keeps
    // the run broken (e.g. clamped probe storage).
    std::vector<std::string> finiteWith;
};

struct CaseSummary {
    std::string group, name, stresses;
    int width = 0, height = 0;
    std::string truth;     // "reference" or "origin" (the truth scene)
    Measurement reference; // the reference frame's own counts (non-finite must be 0)
    int frames = 0;        // frames rendered for this case
};

struct SweepResult {
    StressVariant reference;
    SweepOptions options;
    std::vector<CaseSummary> cases;
    std::vector<StressRun> runs;
};

// Progress lines ("[3/26] light=1e+06: fp16 (guards off) ...") for people.
using SweepProgress = std::function<void(const std::string&)>;

SweepResult runSweep(const std::vector<StressCase>& cases, const SweepOptions& options,
                     StressRenderer& renderer, const SweepProgress& progress = {});

} // namespace pb::stress
