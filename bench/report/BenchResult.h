#pragma once
// Everything one benchmark run measured, GL-free, for the JSON, the Markdown summary and the
// HTML report (ResultJson.h, MarkdownSummary.h, HtmlReport.h). Times in milliseconds.
#include "bench/shaders/ShaderStatistics.h"
#include "AblationPlan.h"
#include "CacheModelSection.h"
#include "DevicePrediction.h"
#include "core/MachineState.h"
#include "metrics/Statistics.h"

#include <nlohmann/json.hpp>

#include <cstdint>

#include <optional>
#include <string>
#include <vector>

namespace pb::bench {

struct SectionTiming {
    std::string name;            // a pass (FrameTimer section) or a sub-section
    std::vector<double> samples; // one per measured frame (warm-up excluded)
    stats::Summary ms;
};

struct CoverageResult {
    double fraction = 0; // pixels needing GI (target 1.0)
    int maxOverlap = 0;  // volumes over one pixel, at most
    double meanOverlap = 0;
};

struct AccuracyResult {
    bool measured = false;
    double flipMean = 0, flipMax = 0; // LDR-FLIP of the tonemapped output vs reference
    double psnr = 0;                  // dB; +inf when identical
    double ssim = 1;
    double relativeMseGi = 0; // linear GI irradiance (the lighting's indirect input)
    std::string heatmapFile;  // FLIP heat-map PNG ("" when none written)
    // The two frames FLIP compared, as PNGs beside the heat map ("" when none written).
    std::string frameFile, referenceFrameFile;
};

// The same frame against the path-traced ground truth of the view (`bench --truth`,
// renderer/truth/): FLIP and PSNR of the tonemapped output, relative MSE of the linear
// radiance (not of the GI irradiance: the truth has no separate GI term).
struct TruthAccuracy {
    bool measured = false;
    double flipMean = 0, flipMax = 0;
    double psnr = 0;        // dB; +inf when identical
    double relativeMse = 0; // linear radiance, sum (t - r)^2 / sum r^2
};

// A profile's error against the truth, split: the reference's own (the probes: their
// resolution, interpolation and the bake) and what the profile's switches add on top (the
// profile's figure minus the reference's; negative where a switch happens to land nearer the
// truth). Both measured only when both frames were. Beside them, when measured, the reference
// with probes of one bounce pass fewer: what the bake's last pass buys.
struct TruthErrorSplit {
    bool measured = false;
    double referenceFlip = 0, referenceRelativeMse = 0;
    double switchesFlip = 0, switchesRelativeMse = 0;
    bool fewerPassesMeasured = false;
    double fewerPassesFlip = 0, fewerPassesRelativeMse = 0;
    // Under all of it, when measured: the direct light's own error (the frame without GI of the
    // sun and punctual lights against their traced light), which no probe set removes.
    bool directMeasured = false;
    double directFlip = 0, directRelativeMse = 0;
};
inline TruthErrorSplit splitTruthError(const TruthAccuracy& profile, const TruthAccuracy& reference,
                                       const TruthAccuracy& fewerPasses = {},
                                       const TruthAccuracy& direct = {}) {
    if (!profile.measured || !reference.measured) return {};
    return {true,
            reference.flipMean,
            reference.relativeMse,
            profile.flipMean - reference.flipMean,
            profile.relativeMse - reference.relativeMse,
            fewerPasses.measured,
            fewerPasses.flipMean,
            fewerPasses.relativeMse,
            direct.measured,
            direct.flipMean,
            direct.relativeMse};
}
// The split of session `s`'s profile, with everything the session measured.
struct SessionResult;
TruthErrorSplit sessionTruthSplit(const SessionResult& s);

// What the report shows side by side per session: the truth, the reference and the profile
// frames (PNG files) and their FLIP heat maps against the truth ("" when not written).
struct TruthPictures {
    std::string truthFile, referenceFile, profileFile, referenceHeatmapFile, profileHeatmapFile;
};

struct VariantResult {
    Variant variant;
    std::string status = "ok"; // "ok" | "unsupported" (error says why)
    std::string error;
    std::vector<SectionTiming> sections; // in first-seen order: the frame's passes
    std::vector<double> frameSamples;    // whole frame, per measured frame
    stats::Summary frameMs;
    std::vector<double> roundMedians;        // frame ms per round (median of its frames)
    // Per round, the first frame after switching to this variant from another (never in the
    // statistics above): what a switch of profile at run time costs on top of a steady frame.
    std::vector<double> switchFrameSamples;
    std::optional<SectionTiming> fetchFloor; // the GI pass's texture-fetch floor
    // One counted frame of the GI pass (GiPassStats, with the fetch floor only; 0 = not
    // counted): its full lookups and its target's texels. The floor does one lookup per texel.
    std::int64_t giEvaluations = 0, giTexels = 0;
    AccuracyResult accuracy;
    TruthAccuracy vsTruth;
    CoverageResult coverage;
    double giMemoryMiB = 0;      // GI memory (profile::kGiMemoryDefinition): probes + targets
    double giProbeMemoryMiB = 0; // of it, the probe textures
    int volumesKept = 0;
    bool ok() const { return status == "ok"; }
    const SectionTiming* section(const std::string& name) const;
};

struct DeltaResult {
    PlannedDelta planned;
    bool measured = false; // both sides rendered
    stats::Shift ms;       // on - off, paired over rounds (Hodges-Lehmann, Wilcoxon CI)
    double flip = 0, psnr = 0, ssim = 0, relativeMseGi = 0; // on - off (psnr: NaN if inf)
};

struct SessionResult {
    Session session;
    std::vector<VariantResult> variants; // parallel to session.variants
    std::vector<DeltaResult> deltas;     // parallel to session.deltas
    // The machine before and after the rounds this session's variants were timed in.
    MachineState machineBefore, machineAfter;
    const VariantResult& profile() const { return variants[0]; }
    const VariantResult& reference() const { return variants[size_t(session.referenceVariant)]; }
    const DeltaResult* vsReference() const;
    TruthPictures truthPictures;
    // `bench --truth`: the reference rendered with the probes of one bounce pass fewer
    // (FewerBouncePasses.h); not measured when they could not be baked.
    TruthAccuracy referenceFewerPassesVsTruth;
    // `bench --truth`: the frame without GI of the scene's sun and punctual lights alone
    // against their traced light (BenchTruth.h directLightScene): the direct light's own error.
    TruthAccuracy directLightVsTruth;
};

struct BenchSettings {
    int frames = 0, rounds = 0, warmup = 0;
    bool ablate = false;
    std::string timingMethod; // "cpu-finish" | "timer-query" | "timer-query-flush"
    std::string timingReason; // why that method
    double pixelsPerDegree = 67;
};

struct BenchResult {
    nlohmann::json context; // platform, GL strings, driver, CPU, threads, commit, date, load
    nlohmann::json scene;   // name, summary, probes file, volumes, probe format
    nlohmann::json view;    // source (worst-case | view | camera), camera spec, coverage
    BenchSettings settings;
    std::vector<SessionResult> sessions;
    double heatmapScale = 1; // FLIP value shown as the ramp's brightest colour in every heat map
    double seconds = 0;      // wall time of the whole run
    std::vector<CacheModelEntry> cacheModel; // per profile (empty: not modelled)
    // `bench --truth`: spp, depth, per image size its noise, time and cache file; null without.
    nlohmann::json truth;
    // `bench --respond`: the event, size and frames, and per profile respond's figures
    // (profiles[]: profile, budgets, schedules[] with t95_frames, t99_frames, rays_per_frame,
    // upload_bytes_per_frame; no error curves); null without.
    nlohmann::json response;
    // `bench --targets`: every profile's programs compiled by the weak GPUs' compilers
    // (bench/shaders/README.md); no targets when not asked for.
    shaders::ShaderStatisticsRun shaderTargets;
    // `bench --predict`: per device the model's frame and pass times and switch deltas beside
    // this machine's (DevicePrediction.h); empty when not asked for.
    std::vector<DevicePrediction> predictions;
};

// Fills `s.deltas` from its plan and its variants' measurements: each delta the paired shift of
// the two sides' round medians (Hodges-Lehmann, Wilcoxon CI), and the accuracy differences
// where both sides were measured. The runner's last step, GL-free.
void pairDeltas(SessionResult& s);

} // namespace pb::bench
