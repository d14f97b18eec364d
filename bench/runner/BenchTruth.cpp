#include "BenchTruth.h"

#include "core/Error.h"
#include "metrics/ImageMetrics.h"
#include "truth/TruthCache.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pb::bench {

namespace {

// Per session size: the truth of `s` with `base`'s depth and spp, from the cache or traced
// (progress per decile); `sizes` receives each size's noise, time and cache file.
TruthBySize traceEverySize(const scene::Scene& s, const scene::View& view, const BenchPlan& plan,
                           truth::TruthSettings base, const BenchTruthOptions& o,
                           const std::string& what, nlohmann::json& sizes) {
    TruthBySize out;
    sizes = nlohmann::json::array();
    for (const Session& session : plan.sessions) {
        const std::pair<int, int> key{session.width, session.height};
        if (out.count(key)) continue;
        truth::TruthSettings ts = base;
        ts.width = session.width;
        ts.height = session.height;
        const std::uint64_t hash = truth::truthInputHash(s, view, ts);
        std::optional<truth::TruthResult> r = truth::loadCachedTruth(o.cacheDir, hash, ts);
        const bool cached = r.has_value();
        const std::string size = std::to_string(ts.width) + "x" + std::to_string(ts.height);
        if (!r) {
            if (o.progress) o.progress("path-tracing " + what + " at " + size + ", " + std::to_string(ts.spp) + " spp");
            int lastDecile = -1;
            r = truth::renderTruth(s, view, ts, [&](int done, int total) {
                int decile = total > 0 ? 10 * done / total : 10;
                if (decile > lastDecile && o.progress && decile < 10)
                    o.progress(what + " " + size + ": " + std::to_string(decile * 10) + "%");
                lastDecile = decile;
            });
            truth::storeCachedTruth(o.cacheDir, hash, *r);
        }
        char line[240];
        std::snprintf(line, sizeof line, "%s %s: mean luminance %.5g +- %.2g (%.3f%%)%s", what.c_str(),
                      size.c_str(), r->noise.meanLuminance, r->noise.standardError,
                      100.0 * r->noise.relativeStandardError, cached ? ", cached" : "");
        if (o.progress) o.progress(line);
        if (!r->note.empty() && o.progress) o.progress("note: " + r->note);
        auto known = [&](double v) { return r->noise.varianceKnown ? nlohmann::json(v) : nlohmann::json(nullptr); };
        sizes.push_back({{"width", ts.width},
                         {"height", ts.height},
                         {"mean_luminance", r->noise.meanLuminance},
                         {"standard_error", known(r->noise.standardError)},
                         {"relative_standard_error", known(r->noise.relativeStandardError)},
                         {"pixel_relative_standard_error", known(r->noise.pixelRelativeStandardError)},
                         {"relative_mse_noise_floor", known(r->noise.relativeMseNoiseFloor)},
                         {"seconds", r->seconds},
                         {"cached", cached},
                         {"cache_file", truth::truthCachePath(o.cacheDir, hash)},
                         {"note", r->note.empty() ? nlohmann::json(nullptr) : nlohmann::json(r->note)}});
        out.emplace(key, std::move(r->hdr));
    }
    return out;
}

} // namespace

TruthBySize computeBenchTruth(const scene::Scene& s, const scene::View& view, const BenchPlan& plan,
                              const BenchTruthOptions& o, nlohmann::json* info) {
    truth::TruthSettings ts;
    ts.spp = o.spp;
    ts.maxDepth = o.maxDepth;
    nlohmann::json sizes;
    TruthBySize out = traceEverySize(s, view, plan, ts, o, "truth", sizes);
    if (info)
        *info = {{"spp", o.spp}, {"max_depth", o.maxDepth}, {"seed", 1}, {"sizes", sizes}, {"heatmap_scale", nullptr}};
    return out;
}

scene::Scene directLightScene(const scene::Scene& s) {
    scene::Scene d = s;
    d.sky.radiance = glm::vec3(0.0f);
    for (scene::Material& m : d.materials) {
        m.emissive = glm::vec3(0.0f);
        m.emissiveTexture = -1;
    }
    return d;
}

bool hasDirectLight(const scene::Scene& s) {
    const bool sun = s.sun.enabled && s.sun.intensity * s.sun.color != glm::vec3(0.0f);
    return sun || !s.lights.empty();
}

TruthBySize computeBenchDirectTruth(const scene::Scene& direct, const scene::View& view,
                                    const BenchPlan& plan, const BenchTruthOptions& o,
                                    nlohmann::json* info) {
    truth::TruthSettings ts;
    ts.spp = std::min(o.spp, kDirectTruthSpp);
    ts.maxDepth = 1;
    nlohmann::json sizes;
    TruthBySize out = traceEverySize(direct, view, plan, ts, o, "direct-light truth", sizes);
    if (info) *info = {{"spp", ts.spp}, {"max_depth", 1}, {"sizes", sizes}};
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
