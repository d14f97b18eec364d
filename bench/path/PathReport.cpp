#include "PathReport.h"

#include "metrics/ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace pb::bench {

namespace {
constexpr double kConvergedRelative = 0.1, kConvergedAbsolute = 1e-4;

nlohmann::json finiteOrNull(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// PSNR of identical frames is +inf, written "inf" in text and null in JSON, as `compare` and
// `bench` write it (it used to count as 100 dB here): the PSNR mean and min are over the
// frames that differ, with the identical ones counted apart.
struct Totals {
    double psnrMean = INFINITY, psnrMin = INFINITY, flipMean = 0, maeMean = 0;
    std::int64_t identical = 0;
    double giRelMse = 0, giRelMae = 0;
    std::int64_t entered = 0, disoccluded = 0;
    double disoccludedMae = 0;      // pixel-weighted over all frames
    double disoccludedGiRelMae = 0; // pixel-weighted over all frames
};

Totals totals(const std::vector<PathFrameError>& frames) {
    Totals t;
    double disoccludedSum = 0, disoccludedGiSum = 0, psnrSum = 0;
    for (const auto& f : frames) {
        t.giRelMse += f.giRelMse;
        t.giRelMae += f.giRelMae;
        disoccludedGiSum += f.disoccludedGiRelMae * double(f.disoccludedPixels);
        if (std::isfinite(f.psnr)) {
            psnrSum += f.psnr;
            t.psnrMin = std::min(t.psnrMin, f.psnr);
        } else {
            ++t.identical;
        }
        t.flipMean += f.flipMean;
        t.maeMean += f.mae;
        t.entered += f.enteredPixels;
        t.disoccluded += f.disoccludedPixels;
        disoccludedSum += f.disoccludedMae * double(f.disoccludedPixels);
    }
    const double n = std::max<double>(1.0, double(frames.size()));
    const std::int64_t differing = std::int64_t(frames.size()) - t.identical;
    if (differing > 0) t.psnrMean = psnrSum / double(differing);
    t.flipMean /= n;
    t.maeMean /= n;
    t.giRelMse /= n;
    t.giRelMae /= n;
    if (t.disoccluded > 0) {
        t.disoccludedMae = disoccludedSum / double(t.disoccluded);
        t.disoccludedGiRelMae = disoccludedGiSum / double(t.disoccluded);
    }
    return t;
}
} // namespace

PathFrameError measurePathFrame(const image::Image8& test, const image::Image8& reference,
                                const image::ImageF& testGi, const image::ImageF& referenceGi,
                                const std::vector<camera::PixelHistory>& history) {
    auto hidden = [&](size_t p) {
        return !history.empty() && history[p] == camera::PixelHistory::WasHidden;
    };
    PathFrameError e;
    e.giRelMse = metrics::relativeMse(testGi, referenceGi);
    double giDiff = 0, giRef = 0, giDiffMasked = 0, giRefMasked = 0;
    for (size_t p = 0; p < size_t(testGi.width) * size_t(testGi.height); ++p)
        for (size_t c = 0; c < 3; ++c) {
            const size_t i = p * size_t(testGi.channels) + c;
            const double d = std::abs(double(testGi.pixels[i]) - referenceGi.pixels[i]);
            const double r = std::abs(double(referenceGi.pixels[i]));
            giDiff += d;
            giRef += r;
            if (hidden(p)) {
                giDiffMasked += d;
                giRefMasked += r;
            }
        }
    e.giRelMae = giRef > 0 ? giDiff / giRef : 0.0;
    e.disoccludedGiRelMae = giRefMasked > 0 ? giDiffMasked / giRefMasked : 0.0;
    e.psnr = metrics::psnr(test, reference);
    const metrics::FlipResult flip = metrics::ldrFlip(test, reference);
    e.flipMean = flip.mean;
    e.flipMax = flip.max;
    double sum = 0, sumMasked = 0;
    const size_t pixels = size_t(test.width) * size_t(test.height);
    for (size_t p = 0; p < pixels; ++p) {
        double d = 0;
        for (size_t c = 0; c < 3; ++c)
            d += std::abs(int(test.pixels[p * 4 + c]) - int(reference.pixels[p * 4 + c]));
        sum += d;
        if (hidden(p)) {
            sumMasked += d;
            ++e.disoccludedPixels;
        }
        if (!history.empty() && history[p] == camera::PixelHistory::EnteredScreen)
            ++e.enteredPixels;
    }
    e.mae = sum / (3.0 * double(pixels));
    if (e.disoccludedPixels > 0) e.disoccludedMae = sumMasked / (3.0 * double(e.disoccludedPixels));
    return e;
}

std::vector<PathConvergence> framesToConverge(const std::vector<PathFrameError>& frames) {
    std::vector<PathConvergence> out;
    for (size_t start = 0; start < frames.size(); ++start) {
        if (!frames[start].cut) continue;
        size_t end = start + 1;
        while (end < frames.size() && !frames[end].cut)
            ++end;
        PathConvergence c;
        c.cutFrame = frames[start].frame;
        if (end - start >= 2) {
            const double last = frames[end - 1].giRelMae;
            const double target =
                std::max(last * (1.0 + kConvergedRelative), last + kConvergedAbsolute);
            size_t k = end - 1;
            while (k > start && frames[k - 1].giRelMae <= target)
                --k;
            c.frames = int(k - start);
        }
        out.push_back(c);
    }
    return out;
}

std::string pathErrorsCsv(const std::vector<PathFrameError>& frames) {
    std::ostringstream out;
    out << "frame,time_s,cut,history_used,psnr_db,flip_mean,flip_max,mae,gi_rel_mse,gi_rel_mae,"
           "entered_pixels,disoccluded_pixels,disoccluded_mae,disoccluded_gi_rel_mae\n";
    char line[256];
    for (const auto& f : frames) {
        std::snprintf(
            line, sizeof line, "%d,%.4f,%d,%d,%s,%.6f,%.6f,%.4f,%.4g,%.4g,%lld,%lld,%.4f,%.4g\n",
            f.frame, f.time, f.cut ? 1 : 0, f.historyUsed ? 1 : 0,
            std::isfinite(f.psnr) ? std::to_string(f.psnr).c_str() : "inf", f.flipMean, f.flipMax,
            f.mae, f.giRelMse, f.giRelMae, static_cast<long long>(f.enteredPixels),
            static_cast<long long>(f.disoccludedPixels), f.disoccludedMae, f.disoccludedGiRelMae);
        out << line;
    }
    return out.str();
}

nlohmann::json pathErrorsJson(const std::vector<PathFrameError>& frames, nlohmann::json about) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& f : frames)
        list.push_back({{"frame", f.frame},
                        {"time_s", f.time},
                        {"cut", f.cut},
                        {"history_used", f.historyUsed},
                        {"psnr_db", finiteOrNull(f.psnr)}, // null = identical
                        {"flip_mean", f.flipMean},
                        {"flip_max", f.flipMax},
                        {"mae", f.mae},
                        {"gi_rel_mse", f.giRelMse},
                        {"gi_rel_mae", f.giRelMae},
                        {"entered_pixels", f.enteredPixels},
                        {"disoccluded_pixels", f.disoccludedPixels},
                        {"disoccluded_mae", f.disoccludedMae},
                        {"disoccluded_gi_rel_mae", f.disoccludedGiRelMae}});
    const Totals t = totals(frames);
    nlohmann::json convergence = nlohmann::json::array();
    for (const auto& c : framesToConverge(frames))
        convergence.push_back({{"cut_frame", c.cutFrame},
                               {"frames_to_converge", c.frames < 0 ? nlohmann::json(nullptr)
                                                                   : nlohmann::json(c.frames)}});
    about["frames"] = list;
    about["summary"] = {{"psnr_mean_db", finiteOrNull(t.psnrMean)}, // of the differing frames
                        {"psnr_min_db", finiteOrNull(t.psnrMin)},
                        {"identical_frames", t.identical}, // PSNR inf (null per frame)
                        {"flip_mean", t.flipMean},
                        {"mae_mean", t.maeMean},
                        {"gi_rel_mse_mean", t.giRelMse},
                        {"gi_rel_mae_mean", t.giRelMae},
                        {"entered_pixels", t.entered},
                        {"disoccluded_pixels", t.disoccluded},
                        {"disoccluded_mae", t.disoccludedMae},
                        {"disoccluded_gi_rel_mae", t.disoccludedGiRelMae},
                        {"convergence", convergence}};
    return about;
}

std::string pathSummaryText(const std::vector<PathFrameError>& frames) {
    const Totals t = totals(frames);
    char line[512];
    std::string out;
    std::snprintf(line, sizeof line,
                  "error vs full-resolution GI over %zu frames: PSNR mean %.2f dB (min %.2f) "
                  "over the %lld that differ, %lld identical (PSNR inf), FLIP mean %.4f, MAE "
                  "%.3f; GI rel. MAE %.4f, rel. MSE %.3g\n",
                  frames.size(), t.psnrMean, t.psnrMin,
                  static_cast<long long>(std::int64_t(frames.size()) - t.identical),
                  static_cast<long long>(t.identical), t.flipMean, t.maeMean, t.giRelMae,
                  t.giRelMse);
    out += line;
    std::snprintf(line, sizeof line,
                  "disocclusions (hidden in the previous frame): %lld pixels, MAE there %.3f, GI "
                  "rel. MAE there %.4f; %lld pixels entered at the borders\n",
                  static_cast<long long>(t.disoccluded), t.disoccludedMae, t.disoccludedGiRelMae,
                  static_cast<long long>(t.entered));
    out += line;
    for (const auto& c : framesToConverge(frames)) {
        if (c.frames < 0)
            std::snprintf(line, sizeof line, "cut at frame %d: segment too short to converge\n",
                          c.cutFrame);
        else
            std::snprintf(line, sizeof line, "cut at frame %d: converged after %d frame(s)\n",
                          c.cutFrame, c.frames);
        out += line;
    }
    return out;
}

} // namespace pb::bench
