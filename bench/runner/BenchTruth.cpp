#include "BenchTruth.h"

#include "core/Error.h"
#include "metrics/ImageMetrics.h"
#include "truth/TruthCache.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pb::bench {

TruthBySize computeBenchTruth(const scene::Scene& s, const scene::View& view, const BenchPlan& plan,
                              const BenchTruthOptions& o, nlohmann::json* info) {
    TruthBySize out;
    nlohmann::json sizes = nlohmann::json::array();
    for (const Session& session : plan.sessions) {
        const std::pair<int, int> key{session.width, session.height};
        if (out.count(key)) continue;
        truth::TruthSettings ts;
        ts.width = session.width;
        ts.height = session.height;
        ts.spp = o.spp;
        ts.maxDepth = o.maxDepth;
        const std::uint64_t hash = truth::truthInputHash(s, view, ts);
        std::optional<truth::TruthResult> r = truth::loadCachedTruth(o.cacheDir, hash, ts);
        const bool cached = r.has_value();
        const std::string size = std::to_string(ts.width) + "x" + std::to_string(ts.height);
        if (!r) {
            if (o.progress) o.progress("path-tracing the truth at " + size + ", " + std::to_string(ts.spp) + " spp");
            int lastDecile = -1;
            r = truth::renderTruth(s, view, ts, [&](int done, int total) {
                int decile = total > 0 ? 10 * done / total : 10;
                if (decile > lastDecile && o.progress && decile < 10)
                    o.progress("truth " + size + ": " + std::to_string(decile * 10) + "%");
                lastDecile = decile;
            });
            truth::storeCachedTruth(o.cacheDir, hash, *r);
        }
        char line[200];
        std::snprintf(line, sizeof line, "truth %s: mean luminance %.5g +- %.2g (%.3f%%)%s", size.c_str(),
                      r->noise.meanLuminance, r->noise.standardError, 100.0 * r->noise.relativeStandardError,
                      cached ? ", cached" : "");
        if (o.progress) o.progress(line);
        if (!r->note.empty() && o.progress) o.progress("note: " + r->note);
        sizes.push_back({{"width", ts.width},
                         {"height", ts.height},
                         {"mean_luminance", r->noise.meanLuminance},
                         {"standard_error", r->noise.varianceKnown ? nlohmann::json(r->noise.standardError) : nlohmann::json(nullptr)},
                         {"relative_standard_error",
                          r->noise.varianceKnown ? nlohmann::json(r->noise.relativeStandardError) : nlohmann::json(nullptr)},
                         {"pixel_relative_standard_error",
                          r->noise.varianceKnown ? nlohmann::json(r->noise.pixelRelativeStandardError) : nlohmann::json(nullptr)},
                         {"relative_mse_noise_floor",
                          r->noise.varianceKnown ? nlohmann::json(r->noise.relativeMseNoiseFloor) : nlohmann::json(nullptr)},
                         {"seconds", r->seconds},
                         {"cached", cached},
                         {"cache_file", truth::truthCachePath(o.cacheDir, hash)},
                         {"note", r->note.empty() ? nlohmann::json(nullptr) : nlohmann::json(r->note)}});
        out.emplace(key, std::move(r->hdr));
    }
    if (info)
        *info = {{"spp", o.spp}, {"max_depth", o.maxDepth}, {"seed", 1}, {"sizes", sizes}, {"heatmap_scale", nullptr}};
    return out;
}

void writeTruthPictures(std::vector<SessionResult>& sessions, const std::vector<TruthMaps>& maps,
                        const std::string& dir, nlohmann::json& info) {
    double scale = 0.05;
    for (const SessionResult& s : sessions)
        for (const VariantResult& v : s.variants)
            if (v.vsTruth.measured) scale = std::max(scale, v.vsTruth.flipMax);
    info["heatmap_scale"] = scale;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("--heatmaps " + dir + ": cannot create the folder");
    for (size_t i = 0; i < sessions.size() && i < maps.size(); ++i) {
        const TruthMaps& m = maps[i];
        TruthPictures& p = sessions[i].truthPictures;
        const std::string base = (std::filesystem::path(dir) / sessions[i].session.profile.name).string();
        auto png = [&](const image::Image8& img, const std::string& suffix, std::string& field) {
            if (img.pixels.empty()) return;
            field = base + suffix;
            image::writePng(field, img);
        };
        auto heat = [&](const image::ImageF& flip, const std::string& suffix, std::string& field) {
            if (flip.pixels.empty()) return;
            field = base + suffix;
            image::writePng(field, metrics::errorHeatMap(flip, float(scale)));
        };
        png(m.truth, "-truth.png", p.truthFile);
        png(m.reference, "-reference.png", p.referenceFile);
        png(m.profile, "-frame.png", p.profileFile);
        heat(m.referenceFlip, "-reference-vs-truth.png", p.referenceHeatmapFile);
        heat(m.profileFlip, "-vs-truth.png", p.profileHeatmapFile);
    }
}

} // namespace pb::bench
