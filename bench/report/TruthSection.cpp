#include "TruthSection.h"

#include "Format.h"
#include "Html.h"

#include <algorithm>
#include <sstream>

namespace pb::bench {
namespace {

bool anyTruth(const BenchResult& r) {
    for (const SessionResult& s : r.sessions)
        for (const VariantResult& v : s.variants)
            if (v.vsTruth.measured) return true;
    return false;
}

std::string sppText(const BenchResult& r) {
    return r.truth.is_object() && r.truth.contains("spp") ? r.truth["spp"].dump() : "?";
}

// The largest relative-MSE noise floor of the truths (the truth's own noise in that figure).
std::string floorText(const BenchResult& r) {
    double worst = -1.0;
    if (r.truth.is_object() && r.truth.contains("sizes"))
        for (const auto& s : r.truth["sizes"])
            if (s.contains("relative_mse_noise_floor") && s["relative_mse_noise_floor"].is_number())
                worst = std::max(worst, s["relative_mse_noise_floor"].get<double>());
    return worst < 0.0 ? std::string() : "; the truth's own noise adds about " + scientific(worst) + " to rel. MSE";
}

// " (8 of 9 passes)" from truth.fewer_bounce_passes, or "" when not baked.
std::string passesText(const BenchResult& r) {
    if (!r.truth.is_object() || !r.truth.contains("fewer_bounce_passes")) return {};
    const nlohmann::json& f = r.truth["fewer_bounce_passes"];
    if (!f.value("baked_passes", nlohmann::json()).is_number()) return {};
    return " (" + f["baked_passes"].dump() + " of " + f["passes"].dump() + " passes)";
}

// "; not measured here: WHY" when the fewer-pass probes could not be baked.
std::string fewerWhyNot(const BenchResult& r) {
    if (!r.truth.is_object() || !r.truth.contains("fewer_bounce_passes")) return {};
    const nlohmann::json& why = r.truth["fewer_bounce_passes"].value("why_not", nlohmann::json());
    return why.is_string() ? "; not measured here: " + why.get<std::string>() : std::string();
}

// The direct-light floor in one sentence (Markdown and HTML).
std::string directLightText(const TruthErrorSplit& split) {
    return "The direct light alone (the frame without GI of the sun and punctual lights, sky and "
           "emission off) is FLIP " + fixed(split.directFlip, 4) + ", rel. MSE " +
           scientific(split.directRelativeMse) +
           " from the traced direct light: the rasterizer's own error (edges without "
           "anti-aliasing against a truth that averages each pixel, the shadow map, unshadowed "
           "punctual lights), under every row's and beyond any probe set's reach.";
}

std::string truthCell(const std::string& text, const std::string& cls = "") {
    return "<td" + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">" + htmlEscape(text) + "</td>";
}

std::string roleText(const SessionResult& s, size_t i) {
    if (i == 0) return "profile";
    if (i == size_t(s.session.referenceVariant)) return "reference";
    return "ablation";
}

void figure(std::ostringstream& h, const std::string& file, const std::string& caption) {
    if (file.empty()) return;
    h << "<figure><img alt=\"" << htmlEscape(caption) << "\" src=\"" << pngDataUri(file)
      << "\"><figcaption>" << htmlEscape(caption) << "</figcaption></figure>\n";
}

} // namespace

std::string truthHtml(const BenchResult& r) {
    if (!anyTruth(r)) return {};
    std::ostringstream h;
    h << "<h2>Against the ground truth</h2>\n<p class=\"note\">The path-traced truth of the same "
         "view (<code>probebench truth</code>, "
      << htmlEscape(sppText(r))
      << " spp" << htmlEscape(floorText(r)) << "): FLIP and PSNR of the tonemapped frame, relative MSE of the linear radiance. The "
         "reference is DDGI from the same probes; its row is how far the probes are from the real "
         "answer. Heat maps on one scale: black 0, pale yellow "
      << htmlEscape(r.truth.is_object() && r.truth.contains("heatmap_scale") ? r.truth["heatmap_scale"].dump() : "?")
      << " or more.</p>\n";
    for (const SessionResult& s : r.sessions) {
        h << "<h3>" << htmlEscape(s.session.profile.name) << " " << s.session.width << "x"
          << s.session.height << "</h3>\n<table class=\"truth\"><tr><th class=\"l\">variant</th>"
             "<th class=\"l\">role</th><th>FLIP mean</th><th>FLIP max</th><th>PSNR dB</th>"
             "<th>rel. MSE</th></tr>\n";
        for (size_t i = 0; i < s.variants.size(); ++i) {
            const VariantResult& v = s.variants[i];
            h << "<tr>" << truthCell(v.variant.label.empty() ? v.variant.id : v.variant.label, "l")
              << truthCell(roleText(s, i), "l");
            if (!v.vsTruth.measured) {
                h << "<td colspan=\"4\">n/a</td></tr>\n";
                continue;
            }
            h << truthCell(fixed(v.vsTruth.flipMean, 4)) << truthCell(fixed(v.vsTruth.flipMax, 3))
              << truthCell(psnrText(v.vsTruth.psnr)) << truthCell(scientific(v.vsTruth.relativeMse))
              << "</tr>\n";
        }
        h << "</table>\n";
        if (const TruthErrorSplit split = sessionTruthSplit(s); split.measured) {
            h << "<p class=\"note\">" << htmlEscape(s.session.profile.name) << "'s error against the truth: "
              << "the reference's own FLIP " << fixed(split.referenceFlip, 4) << ", rel. MSE "
              << htmlEscape(scientific(split.referenceRelativeMse)) << " (the probes); its switches add FLIP "
              << htmlEscape(signedFixed(split.switchesFlip, 4)) << ", rel. MSE "
              << htmlEscape(signedScientific(split.switchesRelativeMse)) << ".";
            if (split.fewerPassesMeasured)
                h << " With one bounce pass fewer" << htmlEscape(passesText(r)) << " the reference is at FLIP "
                  << fixed(split.fewerPassesFlip, 4) << ", rel. MSE "
                  << htmlEscape(scientific(split.fewerPassesRelativeMse)) << ": what the last pass buys.";
            if (split.directMeasured)
                h << " " << htmlEscape(directLightText(split));
            h << "</p>\n";
        }
        const TruthPictures& p = s.truthPictures;
        figure(h, p.truthFile, "truth");
        figure(h, p.referenceFile, "reference: FLIP " + fixed(s.reference().vsTruth.flipMean, 4));
        figure(h, p.profileFile, s.session.profile.name + ": FLIP " + fixed(s.profile().vsTruth.flipMean, 4));
        h << "<br>\n";
        figure(h, p.referenceHeatmapFile, "FLIP reference vs truth");
        figure(h, p.profileHeatmapFile, "FLIP " + s.session.profile.name + " vs truth");
    }
    return h.str();
}

std::string truthMarkdown(const BenchResult& r) {
    if (!anyTruth(r)) return {};
    std::ostringstream out;
    out << "\nAgainst the path-traced truth (" << sppText(r)
        << " spp; FLIP/PSNR of the tonemapped frame, relative MSE of the radiance" << floorText(r)
        << "):\n\n"
        << "| profile | FLIP | PSNR dB | rel. MSE | reference FLIP | reference PSNR dB | reference rel. MSE | switches add: FLIP | switches add: rel. MSE | reference, one bounce pass fewer" << passesText(r) << ": FLIP | its rel. MSE |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SessionResult& s : r.sessions) {
        const TruthAccuracy& p = s.profile().vsTruth;
        const TruthAccuracy& ref = s.reference().vsTruth;
        auto cells = [](const TruthAccuracy& a) {
            return a.measured ? fixed(a.flipMean, 4) + " | " + psnrText(a.psnr) + " | " + scientific(a.relativeMse)
                              : std::string("n/a | n/a | n/a");
        };
        const TruthErrorSplit split = sessionTruthSplit(s);
        const std::string added = split.measured ? signedFixed(split.switchesFlip, 4) + " | " +
                                                       signedScientific(split.switchesRelativeMse)
                                                 : std::string("n/a | n/a");
        const std::string fewer = split.fewerPassesMeasured
                                      ? fixed(split.fewerPassesFlip, 4) + " | " +
                                            scientific(split.fewerPassesRelativeMse)
                                      : std::string("n/a | n/a");
        out << "| " << s.session.profile.name << " | " << cells(p) << " | " << cells(ref) << " | "
            << added << " | " << fewer << " |\n";
    }
    out << "\nThe profile's error is the reference's own (the probes: resolution, interpolation, "
           "the bake) plus what its switches add (the difference; negative: nearer the truth). "
           "The last columns: the reference with probes baked one bounce pass short, so the "
           "difference to the reference's columns is what the bake's last pass buys"
        << fewerWhyNot(r) << ".\n";
    std::string lastSize;
    for (const SessionResult& s : r.sessions) { // one line per size: the floor is the view's
        const std::string size = std::to_string(s.session.width) + "x" + std::to_string(s.session.height);
        const TruthErrorSplit split = sessionTruthSplit(s);
        if (!split.directMeasured || size == lastSize) continue;
        lastSize = size;
        out << "\nAt " << size << ": " << directLightText(split) << "\n";
    }
    return out.str();
}

} // namespace pb::bench
