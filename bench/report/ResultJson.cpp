#include "ResultJson.h"

#include "GiSections.h"
#include "Spread.h"
#include "TimingTrust.h"

#include <cmath>

namespace pb::bench {

nlohmann::json finiteOrNull(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json summaryJson(const stats::Summary& s) {
    return {{"n", s.n},          {"median", s.median},  {"min", s.min},         {"max", s.max},
            {"mean", s.mean},    {"q1", s.q1},          {"q3", s.q3},           {"iqr", s.iqr},
            {"ci_low", s.ciLow}, {"ci_high", s.ciHigh}, {"ci_level", s.ciLevel}};
}

nlohmann::json shiftJson(const stats::Shift& s) {
    return {{"estimate", s.estimate},
            {"ci_low", s.ciLow},
            {"ci_high", s.ciHigh},
            {"ci_level", s.ciLevel}};
}

std::vector<double> giPassSamples(const VariantResult& v) {
    std::vector<double> out(v.frameSamples.size(), 0.0);
    for (const SectionTiming& s : v.sections)
        if (isGiSection(s.name))
            for (size_t i = 0; i < s.samples.size() && i < out.size(); ++i)
                out[i] += s.samples[i];
    return out;
}

double giOverFloor(const VariantResult& v) {
    const std::vector<double> gi = giPassSamples(v);
    if (!v.fetchFloor || gi.empty()) return NAN;
    return stats::summarize(gi).median / v.fetchFloor->ms.median;
}

double giOverFloorPerEvaluation(const VariantResult& v) {
    if (v.giEvaluations <= 0 || v.giTexels <= 0) return NAN;
    return giOverFloor(v) * double(v.giTexels) / double(v.giEvaluations);
}

namespace {

nlohmann::json accuracyJson(const AccuracyResult& a) {
    if (!a.measured) return nullptr;
    return {{"flip_mean", a.flipMean},
            {"flip_max", a.flipMax},
            {"psnr_db", finiteOrNull(a.psnr)},
            {"ssim", a.ssim},
            {"relative_mse_gi", a.relativeMseGi},
            {"heatmap",
             a.heatmapFile.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.heatmapFile)},
            {"frame", a.frameFile.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.frameFile)},
            {"reference_frame", a.referenceFrameFile.empty()
                                    ? nlohmann::json(nullptr)
                                    : nlohmann::json(a.referenceFrameFile)}};
}

// Null without `bench --truth` (or when the variant did not run).
nlohmann::json truthJson(const TruthAccuracy& a) {
    if (!a.measured) return nullptr;
    return {{"flip_mean", a.flipMean},
            {"flip_max", a.flipMax},
            {"psnr_db", finiteOrNull(a.psnr)},
            {"relative_mse", a.relativeMse}};
}

nlohmann::json variantJson(const VariantResult& v, const Session& s) {
    nlohmann::json j{{"id", v.variant.id},
                     {"session", s.profile.name},
                     {"role", roleName(v.variant.role)},
                     {"switch", v.variant.switchKey.empty() ? nlohmann::json(nullptr)
                                                            : nlohmann::json(v.variant.switchKey)},
                     {"label", v.variant.label},
                     {"switches", v.variant.switches.valuesJson()},
                     {"width", s.width},
                     {"height", s.height},
                     {"status", v.status}};
    if (!v.ok()) {
        j["error"] = v.error;
        return j;
    }
    j["frame_ms"] = summaryJson(v.frameMs);
    j["frame_percentiles_ms"] = {{"p50", percentile(v.frameSamples, 0.50)},
                                 {"p90", percentile(v.frameSamples, 0.90)},
                                 {"p99", percentile(v.frameSamples, 0.99)}};
    j["bimodality_coefficient"] = finiteOrNull(bimodalityCoefficient(v.frameSamples));
    nlohmann::json passes = nlohmann::json::array();
    for (const SectionTiming& t : v.sections)
        passes.push_back({{"name", t.name}, {"ms", summaryJson(t.ms)}});
    j["passes"] = passes;
    std::vector<double> gi = giPassSamples(v);
    j["gi_pass_ms"] = gi.empty() ? nlohmann::json(nullptr) : summaryJson(stats::summarize(gi));
    if (v.fetchFloor) {
        j["fetch_floor_ms"] = summaryJson(v.fetchFloor->ms);
        double giMedian = gi.empty() ? 0.0 : stats::summarize(gi).median;
        j["gi_over_floor"] = finiteOrNull(giMedian / v.fetchFloor->ms.median);
        j["gi_over_floor_per_evaluation"] = finiteOrNull(giOverFloorPerEvaluation(v));
    } else {
        j["fetch_floor_ms"] = nullptr;
    }
    if (v.giEvaluations > 0 && v.giTexels > 0) {
        j["gi_evaluations"] = v.giEvaluations;
        j["gi_evaluations_per_texel"] = double(v.giEvaluations) / double(v.giTexels);
    }
    j["accuracy"] = accuracyJson(v.accuracy);
    j["accuracy_vs_truth"] = truthJson(v.vsTruth);
    j["coverage"] = {{"fraction", v.coverage.fraction},
                     {"max_overlap", v.coverage.maxOverlap},
                     {"mean_overlap", v.coverage.meanOverlap}};
    j["gi_memory_mib"] = v.giMemoryMiB;
    j["gi_probe_memory_mib"] = v.giProbeMemoryMiB;
    j["volumes_kept"] = v.volumesKept;
    j["round_medians_ms"] = v.roundMedians;
    j["switch_frame_samples_ms"] = v.switchFrameSamples;
    j["switch_cost_ms"] = finiteOrNull(switchCostMs(v));
    j["frame_samples_ms"] = v.frameSamples;
    return j;
}

nlohmann::json deltaJson(const DeltaResult& d, const SessionResult& s) {
    nlohmann::json j{{"kind", deltaKindName(d.planned.kind)},
                     {"off", s.variants[size_t(d.planned.off)].variant.id},
                     {"on", s.variants[size_t(d.planned.on)].variant.id},
                     {"measured", d.measured}};
    if (!d.measured) return j;
    j["delta_ms"] = shiftJson(d.ms);
    j["delta_flip_mean"] = d.flip;
    j["delta_psnr_db"] = finiteOrNull(d.psnr);
    j["delta_ssim"] = d.ssim;
    j["delta_relative_mse_gi"] = d.relativeMseGi;
    const std::string flags =
        noiseFlags(s.variants[size_t(d.planned.off)], s.variants[size_t(d.planned.on)]);
    j["noise_flags"] = flags.empty() ? nlohmann::json(nullptr) : nlohmann::json(flags);
    // Both sides of the row against the truth (null without --truth).
    j["accuracy_vs_truth"] = {{"off", truthJson(s.variants[size_t(d.planned.off)].vsTruth)},
                              {"on", truthJson(s.variants[size_t(d.planned.on)].vsTruth)}};
    return j;
}

nlohmann::json profileJson(const SessionResult& s, const std::string& renderer) {
    const VariantResult& p = s.profile();
    nlohmann::json j{{"name", s.session.profile.name},
                     {"profile", s.session.profile.toJson()},
                     {"width", s.session.width},
                     {"height", s.session.height},
                     {"variant", p.variant.id},
                     {"reference_variant", s.reference().variant.id},
                     {"status", p.status}};
    if (!p.ok()) j["error"] = p.error;
    if (p.ok()) {
        j["frame_ms"] = summaryJson(p.frameMs);
        // The other side of vs_reference, from the same interleaved rounds.
        j["reference_frame_ms"] =
            s.reference().ok() ? summaryJson(s.reference().frameMs) : nlohmann::json(nullptr);
        j["machine"] = toJson(s.machineBefore, s.machineAfter);
        j["coverage"] = variantJson(p, s.session)["coverage"];
        j["gi_memory_mib"] = p.giMemoryMiB;
        j["gi_probe_memory_mib"] = p.giProbeMemoryMiB;
        const bool judged = budgetJudged(s.session.profile, renderer);
        j["budget"] = {{"device", s.session.profile.budgetDevice},
                       {"judged_here", judged},
                       {"frame_ms", s.session.profile.frameBudgetMs},
                       {"frame_within", judged ? nlohmann::json(p.frameMs.median <=
                                                                s.session.profile.frameBudgetMs)
                                               : nlohmann::json(nullptr)},
                       {"gi_memory_mib", s.session.profile.giMemoryBudgetMiB},
                       {"gi_memory_within", p.giMemoryMiB <= s.session.profile.giMemoryBudgetMiB}};
        j["accuracy"] = accuracyJson(p.accuracy);
        j["accuracy_vs_truth"] = truthJson(p.vsTruth);
        j["reference_accuracy_vs_truth"] = truthJson(s.reference().vsTruth);
        const TruthErrorSplit split = sessionTruthSplit(s);
        auto fewer = [&](double v) {
            return split.fewerPassesMeasured ? nlohmann::json(v) : nlohmann::json(nullptr);
        };
        auto direct = [&](double v) {
            return split.directMeasured ? nlohmann::json(v) : nlohmann::json(nullptr);
        };
        j["truth_error_split"] =
            split.measured
                ? nlohmann::json{{"reference_flip", split.referenceFlip},
                                 {"reference_relative_mse", split.referenceRelativeMse},
                                 {"switches_flip", split.switchesFlip},
                                 {"switches_relative_mse", split.switchesRelativeMse},
                                 {"reference_one_pass_fewer_flip", fewer(split.fewerPassesFlip)},
                                 {"reference_one_pass_fewer_relative_mse",
                                  fewer(split.fewerPassesRelativeMse)},
                                 {"direct_light_flip", direct(split.directFlip)},
                                 {"direct_light_relative_mse", direct(split.directRelativeMse)}}
                : nlohmann::json(nullptr);
        const TruthPictures& tp = s.truthPictures;
        auto file = [](const std::string& f) { return f.empty() ? nlohmann::json(nullptr) : nlohmann::json(f); };
        if (!tp.truthFile.empty())
            j["truth_pictures"] = {{"truth", file(tp.truthFile)},
                                   {"reference", file(tp.referenceFile)},
                                   {"profile", file(tp.profileFile)},
                                   {"reference_heatmap", file(tp.referenceHeatmapFile)},
                                   {"profile_heatmap", file(tp.profileHeatmapFile)}};
    }
    const DeltaResult* vs = s.vsReference();
    j["vs_reference"] = vs ? deltaJson(*vs, s) : nlohmann::json(nullptr); // null: P is reference
    nlohmann::json ablation = nlohmann::json::array();
    for (const DeltaResult& d : s.deltas) {
        if (d.planned.kind != DeltaKind::InProfile) continue;
        nlohmann::json a{{"switch", d.planned.switchKey},
                         {"reference_value", d.planned.offValue},
                         {"profile_value", d.planned.onValue},
                         {"in_profile", deltaJson(d, s)}};
        for (const DeltaResult& o : s.deltas)
            if (o.planned.kind == DeltaKind::OnReference &&
                o.planned.switchKey == d.planned.switchKey)
                a["on_reference"] = deltaJson(o, s);
        ablation.push_back(a);
    }
    j["ablation"] = ablation;
    return j;
}

} // namespace

nlohmann::json benchJson(const BenchResult& r) {
    nlohmann::json j{{"schema", "probebench.bench/1"},
                     {"context", r.context},
                     {"scene", r.scene},
                     {"view", r.view},
                     {"settings",
                      {{"frames", r.settings.frames},
                       {"rounds", r.settings.rounds},
                       {"warmup", r.settings.warmup},
                       {"ablate", r.settings.ablate},
                       {"timing_method", r.settings.timingMethod},
                       {"timing_reason", r.settings.timingReason},
                       {"flip_pixels_per_degree", r.settings.pixelsPerDegree}}},
                     {"heatmap_scale", r.heatmapScale},
                     {"machine_warning", machineWarning(r)},
                     {"seconds", r.seconds}};
    nlohmann::json profiles = nlohmann::json::array(), variants = nlohmann::json::array();
    for (const SessionResult& s : r.sessions) {
        profiles.push_back(profileJson(s, r.context.value("gl_renderer", std::string())));
        for (const VariantResult& v : s.variants)
            variants.push_back(variantJson(v, s.session));
    }
    j["profiles"] = profiles;
    j["variants"] = variants;
    j["cache_model"] = cacheModelJson(r.cacheModel);
    j["truth"] = r.truth; // null without --truth
    if (!r.response.is_null()) j["response"] = r.response; // only with --respond
    if (!r.shaderTargets.targets.empty()) j["shader_targets"] = shaders::toJson(r.shaderTargets);
    if (!r.predictions.empty()) j["device_model"] = predictionsJson(r.predictions);
    return j;
}

} // namespace pb::bench
