#include "HtmlReport.h"

#include "CiLevels.h"
#include "Format.h"
#include "GiSections.h"
#include "Html.h"
#include "ResponseSection.h"
#include "ResultJson.h"
#include "ShaderTargetsSection.h"
#include "SvgCharts.h"
#include "TimingTrust.h"
#include "TruthSection.h"

#include <cmath>
#include <sstream>

namespace pb::bench {

namespace {

const char* kStyle = R"(body{font-family:sans-serif;margin:24px;color:#222;max-width:1200px}
table{border-collapse:collapse;margin:8px 0 20px}th,td{border:1px solid #ccc;padding:3px 7px;
text-align:right;font-size:13px}th{background:#f0f0f0}td.l,th.l{text-align:left}
.note{color:#555;font-size:13px}.bad{color:#b00}.good{color:#060}.ns{color:#888}
figure{display:inline-block;margin:6px;text-align:center;font-size:12px}
figure img{image-rendering:pixelated;border:1px solid #ccc;max-width:360px}
h2{margin-top:32px;border-bottom:1px solid #ddd}code{background:#f4f4f4;padding:1px 3px})";

std::string cell(const std::string& text, const std::string& cls = "") {
    return "<td" + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">" + htmlEscape(text) + "</td>";
}

std::string deltaCell(const DeltaResult* d) {
    if (!d || !d->measured) return cell("n/a");
    return cell(shiftWithCi(d->ms),
                significant(d->ms) ? (d->ms.estimate < 0 ? "good" : "bad") : "ns");
}

void profileTable(std::ostringstream& h, const BenchResult& r) {
    h << "<table id=\"profiles\"><tr><th class=\"l\">profile</th><th>size</th><th>frame ms "
         "median ["
      << htmlEscape(ciLabel(frameCiLevels(r))) << "]</th><th>min</th><th>IQR</th><th>reference "
      << "ms (same rounds)</th><th>Δ ms vs reference [" << htmlEscape(ciLabel(deltaCiLevels(r)))
      << "]</th><th>switch-in ms</th>"
         "<th>budget ms</th><th>GI ms</th><th>fetch floor ms</th><th>GI / floor</th>"
         "<th>GI / floor per evaluation</th>"
         "<th>FLIP mean</th><th>FLIP max</th><th>PSNR dB</th><th>SSIM</th><th>rel. MSE GI</th>"
         "<th>coverage</th><th>GI MiB / budget</th></tr>\n";
    for (const SessionResult& s : r.sessions) {
        const VariantResult& p = s.profile();
        const auto& prof = s.session.profile;
        h << "<tr>" << cell(prof.name, "l")
          << cell(std::to_string(s.session.width) + "x" + std::to_string(s.session.height));
        if (!p.ok()) {
            h << "<td class=\"l bad\" colspan=\"18\">not run: " << htmlEscape(p.error)
              << "</td></tr>\n";
            continue;
        }
        const DeltaResult* vs = s.vsReference();
        std::vector<double> gi = giPassSamples(p);
        double giMs = gi.empty() ? NAN : stats::summarize(gi).median;
        const VariantResult& ref = s.reference();
        const std::string renderer = r.context.value("gl_renderer", std::string());
        h << cell(msWithCi(p.frameMs)) << cell(fixed(p.frameMs.min, 2))
          << cell(fixed(p.frameMs.iqr, 2))
          << cell(ref.ok() ? fixed(ref.frameMs.median, 2) : std::string("n/a"))
          << (vs ? deltaCell(vs) : cell("(reference)")) << cell(switchCostText(p))
          << (budgetJudged(prof, renderer)
                  ? cell(fixed(prof.frameBudgetMs, 1),
                         p.frameMs.median <= prof.frameBudgetMs ? "good" : "bad")
                  : cell(fixed(prof.frameBudgetMs, 1) + " (" + budgetOwnerText(prof) + ")",
                         "ns"))
          << cell(fixed(giMs, 2)) << cell(p.fetchFloor ? fixed(p.fetchFloor->ms.median, 2) : "n/a")
          << cell(p.fetchFloor ? fixed(giMs / p.fetchFloor->ms.median, 2) : "n/a")
          << cell(std::isfinite(giOverFloorPerEvaluation(p)) ? fixed(giOverFloorPerEvaluation(p), 2)
                                                             : "n/a");
        const AccuracyResult& a = p.accuracy;
        h << cell(fixed(a.flipMean, 4)) << cell(fixed(a.flipMax, 3)) << cell(psnrText(a.psnr))
          << cell(fixed(a.ssim, 4)) << cell(scientific(a.relativeMseGi))
          << cell(fixed(p.coverage.fraction, 4), p.coverage.fraction < 1.0 ? "bad" : "")
          << cell(fixed(p.giMemoryMiB, 2) + " / " + fixed(prof.giMemoryBudgetMiB, 1),
                  p.giMemoryMiB <= prof.giMemoryBudgetMiB ? "good" : "bad")
          << "</tr>\n";
    }
    h << "</table>\n<p class=\"note\">GI ms: median per frame of " << kGiSectionsText
      << " (every pass that exists for GI). Reference ms: the reference's median in the same "
         "rounds as the row (every session of one size is timed in one set of interleaved "
         "rounds), the Δ's other side. Switch-in ms: the first frame after switching to the "
         "variant, over its steady median (never in the statistics). A budget is coloured only "
         "when timed on its own device ([budget] device).</p>\n";
}

void charts(std::ostringstream& h, const BenchResult& r) {
    std::vector<ParetoPoint> pts;
    std::vector<StackedBar> bars;
    std::vector<std::string> applied; // "gi.loops=split (in pc-high's session)", by tag
    for (const SessionResult& s : r.sessions) {
        const VariantResult& p = s.profile();
        if (!p.ok()) continue;
        const DeltaResult* vs = s.vsReference();
        if (!vs)
            pts.push_back({s.session.profile.name, 0, 0, 0, 0, true, ""});
        else if (vs->measured)
            pts.push_back({s.session.profile.name, vs->ms.estimate, vs->ms.ciLow, vs->ms.ciHigh,
                           p.accuracy.flipMean, true, ""});
        StackedBar b{s.session.profile.name, {}, p.frameMs.median};
        for (const SectionTiming& t : p.sections)
            b.segments.emplace_back(t.name, t.ms.median);
        bars.push_back(b);
    }
    // One point per switch value applied to the reference (the first session measuring it).
    for (const SessionResult& s : r.sessions)
        for (const DeltaResult& d : s.deltas) {
            if (d.planned.kind != DeltaKind::OnReference || !d.measured) continue;
            std::string what = d.planned.switchKey + "=" + d.planned.onValue;
            bool seen = false;
            for (const auto& a : applied)
                seen |= a.rfind(what + " ", 0) == 0;
            if (seen) continue;
            applied.push_back(what + " (measured in the " + s.session.profile.name + " session, " +
                              std::to_string(s.session.width) + "x" +
                              std::to_string(s.session.height) + ")");
            pts.push_back({what, d.ms.estimate, d.ms.ciLow, d.ms.ciHigh,
                           s.variants[size_t(d.planned.on)].accuracy.flipMean, false,
                           std::to_string(applied.size())});
        }
    h << "<h2>Speed and accuracy (Pareto)</h2>\n<p class=\"note\">Each profile against "
         "<code>reference</code> on the same frame (filled), and single switches applied to the "
         "reference (numbered, from the ablation). Dashed: the points nothing beats on both "
         "axes. Horizontal bars: "
      << htmlEscape(ciLabel(deltaCiLevels(r))) << " of the time delta.</p>\n"
      << paretoSvg(pts, ciLabel(deltaCiLevels(r)));
    if (!applied.empty()) {
        h << "<ol class=\"note\" id=\"pareto-switches\">";
        for (const auto& a : applied)
            h << "<li><code>+" << htmlEscape(a.substr(0, a.find(' '))) << "</code>"
              << htmlEscape(a.substr(a.find(' '))) << "</li>";
        h << "</ol>\n";
    }
    h << "<h2>Time per pass</h2>\n" << stackedBarsSvg(bars);
}

void ablation(std::ostringstream& h, const BenchResult& r) {
    bool header = false;
    for (const SessionResult& s : r.sessions) {
        std::vector<const DeltaResult*> rows;
        for (const DeltaResult& d : s.deltas)
            if (d.planned.kind == DeltaKind::InProfile) rows.push_back(&d);
        if (rows.empty()) continue;
        if (!header) {
            h << "<h2>Ablation: what each switch saves and costs</h2>\n<p class=\"note\">Δ = "
                 "switch on − switch off, paired over interleaved rounds (Hodges-Lehmann estimate, "
                 "Wilcoxon "
              << htmlEscape(ciLabel(deltaCiLevels(r)))
              << "); green: faster with the switch, red: slower, grey: the interval "
                 "contains 0. ΔFLIP &gt; 0: the switch costs accuracy.</p>\n";
            header = true;
        }
        h << "<h3>" << htmlEscape(s.session.profile.name) << "</h3>\n<table class=\"ablation\">"
          << "<tr><th class=\"l\">switch</th><th class=\"l\">reference → profile</th><th>Δ ms in "
             "profile</th><th>ΔFLIP</th><th>ΔPSNR</th><th>Δ rel. MSE GI</th><th>Δ ms on "
             "reference</th><th>ΔFLIP</th></tr>\n";
        for (const DeltaResult* d : rows) {
            const DeltaResult* onRef = nullptr;
            for (const DeltaResult& o : s.deltas)
                if (o.planned.kind == DeltaKind::OnReference &&
                    o.planned.switchKey == d->planned.switchKey)
                    onRef = &o;
            h << "<tr>" << cell(d->planned.switchKey, "l")
              << cell(d->planned.offValue + " → " + d->planned.onValue, "l") << deltaCell(d)
              << cell(d->measured ? fixed(d->flip, 4) : "n/a")
              << cell(d->measured ? fixed(d->psnr, 2) : "n/a")
              << cell(d->measured ? scientific(d->relativeMseGi) : "n/a") << deltaCell(onRef)
              << cell(onRef && onRef->measured ? fixed(onRef->flip, 4) : "n/a") << "</tr>\n";
        }
        h << "</table>\n";
    }
}

void heatmaps(std::ostringstream& h, const BenchResult& r) {
    bool any = false;
    for (const SessionResult& s : r.sessions) {
        const AccuracyResult& a = s.profile().accuracy;
        if (a.heatmapFile.empty()) continue;
        if (!any)
            h << "<h2>FLIP error vs reference</h2>\n<p class=\"note\">Per profile: the "
                 "reference's frame, the profile's frame (both as rendered and tonemapped, the "
                 "images FLIP compares) and the per-pixel LDR-FLIP between them, one scale for "
                 "all heat maps: black 0, pale yellow "
              << fixed(r.heatmapScale, 3) << " or more.</p>\n";
        any = true;
        const std::string name = htmlEscape(s.session.profile.name);
        h << "<div class=\"frames\">\n";
        if (!a.referenceFrameFile.empty())
            h << "<figure><img alt=\"reference frame for " << name << "\" src=\""
              << pngDataUri(a.referenceFrameFile)
              << "\"><figcaption>reference frame</figcaption></figure>\n";
        if (!a.frameFile.empty())
            h << "<figure><img alt=\"frame " << name << "\" src=\"" << pngDataUri(a.frameFile)
              << "\"><figcaption>" << name << " frame</figcaption></figure>\n";
        h << "<figure><img alt=\"FLIP heat map " << name << "\" src=\""
          << pngDataUri(a.heatmapFile) << "\"><figcaption>FLIP " << name << " vs reference: mean "
          << fixed(a.flipMean, 4) << "</figcaption></figure>\n</div>\n";
    }
}

void context(std::ostringstream& h, const BenchResult& r) {
    h << "<h2>Context</h2>\n<table id=\"context\">\n";
    for (auto it = r.context.begin(); it != r.context.end(); ++it)
        h << "<tr><th class=\"l\">" << htmlEscape(it.key()) << "</th><td class=\"l\">"
          << htmlEscape(it->is_string() ? it->get<std::string>() : it->dump()) << "</td></tr>\n";
    h << "<tr><th class=\"l\">timing</th><td class=\"l\">" << htmlEscape(r.settings.timingMethod)
      << ": " << htmlEscape(r.settings.timingReason) << "</td></tr>\n"
      << "<tr><th class=\"l\">rounds x frames (warm-up)</th><td class=\"l\">" << r.settings.rounds
      << " x " << r.settings.frames << " (" << r.settings.warmup
      << " excluded)</td></tr>\n</table>\n";
}

} // namespace

std::string htmlReport(const BenchResult& r) {
    std::ostringstream h;
    const std::string sceneName = r.scene.value("name", std::string("?"));
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>probebench: "
      << htmlEscape(sceneName) << "</title>\n<style>" << kStyle << "</style></head><body>\n"
      << "<h1>probebench bench: " << htmlEscape(sceneName)
      << "</h1>\n<p class=\"note\">View: " << htmlEscape(r.view.value("source", std::string("?")))
      << " <code>--camera " << htmlEscape(r.view.value("camera", std::string("?"))) << "</code>; "
      << htmlEscape(r.context.value("gl_renderer", std::string("?"))) << "; "
      << htmlEscape(r.context.value("date", std::string("?"))) << "; commit "
      << htmlEscape(r.context.value("commit", std::string("?"))) << ".</p>\n";
    if (r.context.value("software_renderer", false))
        h << "<p class=\"note bad\">Software rasterizer: frame times are of this CPU, not of the "
             "target GPUs (budgets shown for reference only). Accuracy, GI memory and coverage "
             "are hardware-independent.</p>\n";
    if (const std::string w = roundsWarning(r.settings.rounds); !w.empty())
        h << "<p class=\"note bad\" id=\"ci-warning\">Warning: " << htmlEscape(w) << ".</p>\n";
    if (const std::string w = machineWarning(r); !w.empty())
        h << "<p class=\"note bad\" id=\"machine-warning\">Warning: " << htmlEscape(w)
          << ".</p>\n";
    h << "<h2>Profiles</h2>\n";
    profileTable(h, r);
    h << "<p class=\"note\">GI MiB: " << htmlEscape(profile::kGiMemoryDefinition)
      << "; the budget is the profile's [budget] gi_memory_mib, which tune budgets the same way.</p>\n";
    h << responseHtml(r); // beside the frame times it is the price of
    charts(h, r);
    ablation(h, r);
    h << cacheModelHtml(r.cacheModel);
    h << shaderTargetsHtml(r);
    h << predictionsHtml(r.predictions);
    heatmaps(h, r);
    h << truthHtml(r);
    context(h, r);
    h << "</body></html>\n";
    return h.str();
}

} // namespace pb::bench
