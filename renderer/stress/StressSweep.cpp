#include "stress/StressSweep.h"

#include <exception>
#include <map>
#include <memory>

namespace pb::stress {

namespace {

// One case's frames: the reference radiance and every measured settings key.
class CaseFrames {
public:
    CaseFrames(const CaseData& data, const image::ImageF& truth, StressRenderer& renderer,
               const BreakThresholds& t)
        : data_(data), truth_(truth), renderer_(renderer), thresholds_(t) {}

    // `seen` (optional) receives the frame when it is rendered now (not from the cache).
    const Measurement& measure(const StressVariant& v,
                               const std::function<void(const RenderedFrame&)>& seen = {}) {
        const std::string key = v.settingsKey();
        auto it = cache_.find(key);
        if (it != cache_.end()) return it->second;
        Measurement m;
        try {
            RenderedFrame f = renderer_.render(data_, v);
            m = compareRadiance(f.radiance, truth_);
            m.nonfiniteGiTexels = f.nonfiniteGiTexels;
            if (seen) seen(f);
        } catch (const std::exception& e) {
            m.error = e.what();
        }
        ++frames_;
        return cache_.emplace(key, m).first->second;
    }
    bool broken(const StressVariant& v) { return stress::broken(measure(v), thresholds_); }
    // A frame rendered outside (the reference of this very case): not rendered again.
    void remember(const StressVariant& v, const Measurement& m) {
        cache_.emplace(v.settingsKey(), m);
    }
    int frames() const { return frames_; }

private:
    const CaseData& data_;
    const image::ImageF& truth_;
    StressRenderer& renderer_;
    BreakThresholds thresholds_;
    std::map<std::string, Measurement> cache_;
    int frames_ = 0;
};

std::string assignment(const StressVariant& v, const std::string& key) {
    return key + "=" + v.get(key);
}

void findCulprits(CaseFrames& frames, const StressVariant& run, StressRun& out) {
    StressVariant base = referenceVariant();
    for (const std::string& g : guardKeys())
        base.set(g, run.get(g));
    if (frames.broken(base)) {
        out.culprits = {"(no switch: the reference breaks too)"};
        return;
    }
    std::vector<std::string> keys;
    for (const std::string& k : run.differingKeys(base))
        if (!isGuardKey(k)) keys.push_back(k);
    for (const std::string& k : keys) {
        StressVariant alone = base;
        alone.set(k, run.get(k));
        if (frames.broken(alone)) out.culprits.push_back(assignment(run, k));
    }
    if (!out.culprits.empty()) return;
    for (const std::string& k : keys) {
        StressVariant reverted = run;
        reverted.set(k, base.get(k));
        if (!frames.broken(reverted)) out.culprits.push_back(assignment(run, k));
    }
    if (out.culprits.empty()) {
        std::string all;
        for (const std::string& k : keys)
            all += (all.empty() ? "" : " + ") + assignment(run, k);
        out.culprits = {"(combination: " + all + ")"};
    }
}

void findGuards(CaseFrames& frames, const StressVariant& run, StressRun& out) {
    std::vector<std::string> off;
    for (const std::string& g : guardKeys())
        if (run.get(g) == "off") off.push_back(g);
    for (const std::string& g : off) {
        StressVariant on = run;
        on.set(g, "on");
        if (!frames.broken(on)) out.fixedBy.push_back(g + "=on");
        if (out.symptom == "nan/inf" && frames.measure(on).error.empty() &&
            frames.measure(on).nonfinitePixels == 0)
            out.finiteWith.push_back(g + "=on");
    }
    if (!out.fixedBy.empty() || off.size() < 2) return;
    StressVariant all = run;
    for (const std::string& g : off)
        all.set(g, "on");
    if (!frames.broken(all)) out.fixedBy.push_back("(all guards together)");
}

std::vector<std::pair<StressVariant, bool>> runsOf(const StressVariant& v, RunGuards g) {
    std::vector<std::pair<StressVariant, bool>> out;
    if (g != RunGuards::Off) out.emplace_back(v, false);
    if (g != RunGuards::AsGiven) out.emplace_back(withoutGuards(v), true);
    return out;
}

} // namespace

SweepResult runSweep(const std::vector<StressCase>& cases, const SweepOptions& options,
                     StressRenderer& renderer, const SweepProgress& progress) {
    SweepResult result;
    result.reference = referenceVariant();
    result.options = options;
    const auto say = [&](const std::string& s) {
        if (progress) progress(s);
    };
    for (std::size_t ci = 0; ci < cases.size(); ++ci) {
        const StressCase& c = cases[ci];
        const std::string tag =
            "[" + std::to_string(ci + 1) + "/" + std::to_string(cases.size()) + "] " + c.name;
        say(tag + ": building the scene and baking");
        const CaseData data = c.build();
        CaseSummary summary{c.group,     c.name,
                            c.stresses,  data.width,
                            data.height, c.buildTruth ? "origin" : "reference",
                            {},          0};
        say(tag + ": reference frame " + std::to_string(data.width) + "x" +
            std::to_string(data.height));
        image::ImageF truth;
        try {
            RenderedFrame f = c.buildTruth ? renderer.render(c.buildTruth(), result.reference)
                                           : renderer.render(data, result.reference);
            if (options.onFrame) options.onFrame(c.name, "reference", f);
            truth = std::move(f.radiance);
            summary.reference = compareRadiance(truth, truth);
        } catch (const std::exception& e) {
            summary.reference.error = e.what();
        }
        summary.frames = 1;
        CaseFrames frames(data, truth, renderer, options.thresholds);
        if (!c.buildTruth && summary.reference.error.empty())
            frames.remember(result.reference, summary.reference);
        for (const StressVariant& v : options.variants)
            for (const auto& [variant, guardsOff] : runsOf(v, options.guards)) {
                say(tag + ": " + v.name + (guardsOff ? " (guards off)" : ""));
                StressRun run;
                run.caseName = c.name;
                run.variant = v.name;
                run.guardsOff = guardsOff;
                if (!summary.reference.error.empty()) {
                    run.m.error = "the reference frame failed: " + summary.reference.error;
                } else {
                    const std::string label = v.name + (guardsOff ? "/off" : "");
                    run.m = frames.measure(variant, [&](const RenderedFrame& f) {
                        if (options.onFrame) options.onFrame(c.name, label, f);
                    });
                }
                run.symptom = symptom(run.m, options.thresholds);
                if (options.analyse && run.symptom != "ok" && run.m.error.empty()) {
                    findCulprits(frames, variant, run);
                    findGuards(frames, variant, run);
                }
                result.runs.push_back(std::move(run));
            }
        summary.frames += frames.frames();
        result.cases.push_back(std::move(summary));
    }
    return result;
}

} // namespace pb::stress
