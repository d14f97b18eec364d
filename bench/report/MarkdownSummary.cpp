#include "MarkdownSummary.h"

#include "CiLevels.h"
#include "Format.h"
#include "GiSections.h"
#include "ResponseSection.h"
#include "ResultJson.h"
#include "ShaderTargetsSection.h"
#include "Spread.h"
#include "TimingTrust.h"
#include "TruthSection.h"

#include <cmath>
#include <sstream>

namespace pb::bench {

namespace {

std::string accuracyCells(const AccuracyResult& a) {
    if (!a.measured) return "n/a | n/a | n/a | n/a";
    return fixed(a.flipMean, 4) + " | " + psnrText(a.psnr) + " | " + fixed(a.ssim, 4) + " | " +
           scientific(a.relativeMseGi);
}

std::string deltaCells(const DeltaResult* d) {
    if (!d || !d->measured) return "n/a | n/a";
    const bool noCi = !(d->ms.ciLevel > 0); // "[no CI]" says it already
    return shiftWithCi(d->ms) + (significant(d->ms) || noCi ? "" : " (ns)") + " | " +
           (d->flip >= 0 ? "+" : "") + fixed(d->flip, 4);
}

// Percentiles and the noise flags of each profile's delta vs the reference: a median delta
// between two bimodal or differently noisy distributions needs a second look.
void spreadTable(std::ostringstream& out, const BenchResult& r) {
    out << "\nFrame ms percentiles (every measured frame) and noise flags of the delta vs "
           "reference (bimodal: Sarle's coefficient > 5/9; variance: ratio > 4):\n\n"
        << "| profile | p50 | p90 | p99 | flags |\n|---|---|---|---|---|\n";
    for (const SessionResult& s : r.sessions) {
        const VariantResult& p = s.profile();
        if (!p.ok()) continue;
        const DeltaResult* vs = s.vsReference();
        const std::string flags =
            vs && vs->measured ? noiseFlags(s.variants[size_t(vs->planned.off)], p) : "";
        out << "| " << s.session.profile.name << " | " << fixed(percentile(p.frameSamples, 0.5), 2)
            << " | " << fixed(percentile(p.frameSamples, 0.9), 2) << " | "
            << fixed(percentile(p.frameSamples, 0.99), 2) << " | " << (flags.empty() ? "-" : flags)
            << " |\n";
    }
}

// "2.51 (5.03)": GI over the fetch floor per evaluation (per texel); "n/a" where not measured.
std::string floorRatioCell(const VariantResult& p) {
    const double perTexel = giOverFloor(p), perEval = giOverFloorPerEvaluation(p);
    if (!std::isfinite(perTexel)) return "n/a";
    return (std::isfinite(perEval) ? fixed(perEval, 2) : std::string("n/a")) + " (" +
           fixed(perTexel, 2) + ")";
}

void markdownProfileTable(std::ostringstream& out, const BenchResult& r) {
    out << "| profile | size | frame ms median [" << ciLabel(frameCiLevels(r))
        << "] | reference ms (same rounds) | Δ ms vs reference [" << ciLabel(deltaCiLevels(r))
        << "] | switch-in ms | GI ms | "
           "floor ms | GI / floor per eval. (per texel) | FLIP | PSNR dB | SSIM | rel. MSE GI | "
           "coverage | GI MiB (budget) |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SessionResult& s : r.sessions) {
        const VariantResult& p = s.profile();
        out << "| " << s.session.profile.name << " | " << s.session.width << "x" << s.session.height
            << " | ";
        if (!p.ok()) {
            out << "not run: " << p.error << " |";
            for (int i = 0; i < 12; ++i)
                out << " - |";
            out << "\n";
            continue;
        }
        const DeltaResult* vs = s.vsReference();
        std::vector<double> gi = giPassSamples(p);
        const VariantResult& ref = s.reference();
        out << msWithCi(p.frameMs) << " | "
            << (ref.ok() ? fixed(ref.frameMs.median, 2) : std::string("n/a")) << " | "
            << (vs ? (vs->measured ? shiftWithCi(vs->ms) : std::string("n/a"))
                   : std::string("(is the reference)"))
            << " | " << switchCostText(p) << " | " << (gi.empty() ? "n/a" : fixed(stats::summarize(gi).median, 2)) << " | "
            << (p.fetchFloor ? fixed(p.fetchFloor->ms.median, 2) : std::string("n/a")) << " | "
            << floorRatioCell(p) << " | " << accuracyCells(p.accuracy) << " | "
            << fixed(p.coverage.fraction, 4) << " | " << fixed(p.giMemoryMiB, 2) << " ("
            << fixed(s.session.profile.giMemoryBudgetMiB, 1) << ") |\n";
    }
    out << "\nReference ms: the reference's median in the same interleaved rounds as the row (the "
           "Δ's other side). Switch-in ms: the first frame after switching to the variant, over "
           "its steady median (never in the statistics).\n"
        << "GI ms: median per frame of " << kGiSectionsText
        << " (every pass that exists for GI; absent passes count 0).\n"
        << "GI / floor: GI ms per evaluation (one lookup of one volume, one counted frame) over "
           "the fetch floor's ms per texel (one lookup's fetches); per texel in parentheses.\n"
        << "GI MiB: " << profile::kGiMemoryDefinition
        << " (what tune's --budget-mib budgets); the budget is the profile's.\n";
    spreadTable(out, r);
}

void passTable(std::ostringstream& out, const BenchResult& r) {
    std::vector<std::string> names = sectionNames(r);
    out << "\nMedian ms per pass (IQR in parentheses: the pass's spread):\n\n| profile |";
    for (const auto& n : names)
        out << " " << n << " |";
    out << " frame |\n|---|";
    for (size_t i = 0; i <= names.size(); ++i)
        out << "---|";
    out << "\n";
    for (const SessionResult& s : r.sessions) {
        const VariantResult& p = s.profile();
        if (!p.ok()) continue;
        out << "| " << s.session.profile.name << " |";
        for (const auto& n : names) {
            const SectionTiming* t = p.section(n);
            out << " "
                << (t ? fixed(t->ms.median, 2) + " (" + fixed(t->ms.iqr, 2) + ")" : std::string("-"))
                << " |";
        }
        out << " " << fixed(p.frameMs.median, 2) << " |\n";
    }
}

void ablationTables(std::ostringstream& out, const BenchResult& r) {
    for (const SessionResult& s : r.sessions) {
        bool any = false;
        for (const DeltaResult& d : s.deltas)
            any |= d.planned.kind == DeltaKind::InProfile;
        if (!any) continue;
        out << "\nAblation of **" << s.session.profile.name
            << "** (Δ = switch on − off; negative ms = the switch saves time; ΔFLIP > 0 = it "
               "costs accuracy; (ns) = the "
            << ciLabel(deltaCiLevels(r)) << " contains 0):\n\n"
            << "| switch | reference → profile | Δ ms in profile | ΔFLIP in profile | Δ ms on "
               "reference | ΔFLIP on reference |\n|---|---|---|---|---|---|\n";
        for (const DeltaResult& d : s.deltas) {
            if (d.planned.kind != DeltaKind::InProfile) continue;
            const DeltaResult* onRef = nullptr;
            for (const DeltaResult& o : s.deltas)
                if (o.planned.kind == DeltaKind::OnReference &&
                    o.planned.switchKey == d.planned.switchKey)
                    onRef = &o;
            out << "| " << d.planned.switchKey << " | " << d.planned.offValue << " → "
                << d.planned.onValue << " | " << deltaCells(&d) << " | " << deltaCells(onRef)
                << " |\n";
        }
    }
}

} // namespace

std::string markdownSummary(const BenchResult& r) {
    std::ostringstream out;
    const auto& ctx = r.context;
    out << "## probebench bench: " << r.scene.value("name", std::string("?")) << ", view "
        << r.view.value("source", std::string("?")) << "\n\n"
        << "Device: " << ctx.value("gl_renderer", std::string("?")) << " ("
        << ctx.value("platform", std::string("?")) << "; "
        << (!ctx.contains("debug_context") || ctx["debug_context"].is_null()
                ? "debug context: unknown"
                : ctx["debug_context"].get<bool>() ? "a debug context (KHR_debug checks timed too)"
                                                   : "a non-debug context")
        << "), timing " << r.settings.timingMethod
        << "; " << r.settings.rounds << " rounds x " << r.settings.frames << " frames after "
        << r.settings.warmup << " warm-up frames per variant; " << fixed(r.seconds, 1) << " s.";
    if (ctx.value("software_renderer", false))
        out << " **Software rasterizer: the times are of this CPU, not of a GPU; accuracy, memory "
               "and coverage are hardware-independent.**";
    if (const std::string w = roundsWarning(r.settings.rounds); !w.empty())
        out << " **Warning: " << w << ".**";
    if (const std::string w = machineWarning(r); !w.empty()) out << " **Warning: " << w << ".**";
    out << "\n\n";
    markdownProfileTable(out, r);
    out << responseMarkdown(r); // beside the frame times it is the price of
    passTable(out, r);
    ablationTables(out, r);
    out << cacheModelMarkdown(r.cacheModel);
    out << shaderTargetsMarkdown(r);
    out << predictionsMarkdown(r.predictions);
    out << truthMarkdown(r);
    return out.str();
}

} // namespace pb::bench
