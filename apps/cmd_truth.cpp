// probebench truth: the path-traced ground truth of one view (renderer/truth/): the same camera,
// materials, lights, exposure and tonemap as `render`, converged by spp, with its own noise
// estimate; cached by input hash next to the baked probes.
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "SceneOptions.h"
#include "bench/runner/ProbeCache.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "image/Image.h"
#include "truth/TruthCache.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace pb::app {
namespace {

struct TruthArgs {
    SceneArgs scene;
    std::string view, camera;
    truth::TruthSettings settings;
    std::string outHdr, out, json, cacheDir;
    bool mkdir = false; // create missing parent folders of the outputs
    const CLI::Option* jsonOption = nullptr;
    float exposure = 0.0f; // 0 = the scene's
    bool noCache = false;
};

// A percentage on a terminal (rewritten in place), a line per 10% otherwise (logs, CI).
class TruthProgress {
public:
    TruthProgress() : tty_(::isatty(::fileno(stderr)) != 0) {}
    void operator()(int done, int total) {
        int pct = total > 0 ? int(100.0 * done / total) : 100;
        if (tty_) {
            std::fprintf(stderr, "\rtruth: %3d%% of %d rows", pct, total);
            std::fflush(stderr);
        } else if (pct / 10 > last_ / 10 || (pct == 100 && last_ < 100)) {
            std::fprintf(stderr, "truth: %d%% of %d rows\n", pct, total);
        }
        last_ = pct;
    }
    void done() {
        if (tty_) std::fprintf(stderr, "\r%-40s\r", "");
    }

private:
    bool tty_;
    int last_ = -1;
};

nlohmann::json toJson(const TruthArgs& a, const scene::Scene& s, const scene::View& v,
                      const truth::TruthResult& r, std::uint64_t hash, bool cached,
                      const std::string& cachePath) {
    const truth::TruthNoise& n = r.noise;
    auto orNull = [](const std::string& x) { return x.empty() ? nlohmann::json(nullptr) : nlohmann::json(x); };
    return {{"scene", s.name},
            {"camera", {{"name", v.name},
                        {"position", {v.position.x, v.position.y, v.position.z}},
                        {"target", {v.target.x, v.target.y, v.target.z}},
                        {"fov_y_degrees", v.fovYDegrees}}},
            {"width", a.settings.width},
            {"height", a.settings.height},
            {"spp", a.settings.spp},
            {"max_depth", a.settings.maxDepth},
            {"seed", a.settings.seed},
            {"exposure", a.exposure > 0.0f ? a.exposure : s.exposure},
            {"mean_luminance", n.meanLuminance},
            // Null with --spp 1: one sample gives no variance.
            {"standard_error", n.varianceKnown ? nlohmann::json(n.standardError) : nlohmann::json(nullptr)},
            {"relative_standard_error",
             n.varianceKnown ? nlohmann::json(n.relativeStandardError) : nlohmann::json(nullptr)},
            {"pixel_relative_standard_error",
             n.varianceKnown ? nlohmann::json(n.pixelRelativeStandardError) : nlohmann::json(nullptr)},
            {"relative_mse_noise_floor",
             n.varianceKnown ? nlohmann::json(n.relativeMseNoiseFloor) : nlohmann::json(nullptr)},
            {"camera_rays", r.cameraRays},
            {"seconds", r.seconds},
            {"cached", cached},
            {"input_hash", std::to_string(hash)},
            {"cache_file", orNull(cachePath)},
            {"out_hdr", orNull(a.outHdr)},
            {"out", orNull(a.out)},
            {"note", orNull(r.note)}};
}

int runTruth(TruthArgs& a) {
    if (a.settings.spp < 1)
        throw UsageError("--spp: must be at least 1 (got " + std::to_string(a.settings.spp) + ")");
    if (!(a.exposure >= 0.0f) || !std::isfinite(a.exposure)) throw UsageError("--exposure: must be > 0");
    const bool jsonToStdout = a.jsonOption && a.jsonOption->count() > 0 && (a.json.empty() || a.json == "-");
    for (const auto& [path, opt] : {std::pair{a.outHdr, "--out-hdr"}, {a.out, "--out"},
                                    {jsonToStdout ? std::string() : a.json, "--json"}})
        if (!path.empty()) prepareOutputParent(opt, path, a.mkdir);

    scene::Scene s = loadSceneWithOverrides(a.scene);
    const scene::View view = chooseView(s, a.view, a.camera);
    const float exposure = a.exposure > 0.0f ? a.exposure : s.exposure;

    const std::uint64_t hash = truth::truthInputHash(s, view, a.settings);
    const std::string cacheDir = a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir;
    std::optional<truth::TruthResult> cached;
    if (!a.noCache) cached = truth::loadCachedTruth(cacheDir, hash, a.settings);
    truth::TruthResult result;
    if (cached) {
        result = std::move(*cached);
    } else {
        TruthProgress progress;
        result = truth::renderTruth(s, view, a.settings, [&](int d, int t) { progress(d, t); });
        progress.done();
        if (!a.noCache) truth::storeCachedTruth(cacheDir, hash, result);
    }
    // Everything is computed before anything is written (each writer renames a temporary).
    if (!a.outHdr.empty()) image::writePfm(a.outHdr, result.hdr);
    if (!a.out.empty()) image::writePng(a.out, truth::tonemap(result.hdr, exposure));
    const std::string cachePath = a.noCache ? std::string() : truth::truthCachePath(cacheDir, hash);
    const nlohmann::json j = toJson(a, s, view, result, hash, cached.has_value(), cachePath);
    if (!a.json.empty() && !jsonToStdout) {
        const std::string text = j.dump(2) + "\n";
        writeFileAtomic(a.json, text.data(), text.size());
    }
    if (!result.note.empty()) std::cerr << "probebench: note: " << result.note << "\n";
    if (jsonToStdout) {
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    const truth::TruthNoise& n = result.noise;
    char line[256];
    std::snprintf(line, sizeof line, "truth: %s, camera '%s', %dx%d, %d spp, depth %d: %s%.1f s\n",
                  s.name.c_str(), view.name.c_str(), a.settings.width, a.settings.height,
                  a.settings.spp, a.settings.maxDepth, cached ? "cached, computed in " : "",
                  result.seconds);
    std::cout << line;
    if (n.varianceKnown)
        std::snprintf(line, sizeof line,
                      "mean luminance %.6g +- %.3g (standard error, %.3f%% relative); per pixel "
                      "%.1f%% (RMS); relative MSE noise floor %.2e\n",
                      n.meanLuminance, n.standardError, 100.0 * n.relativeStandardError,
                      100.0 * n.pixelRelativeStandardError, n.relativeMseNoiseFloor);
    else
        std::snprintf(line, sizeof line, "mean luminance %.6g (no noise estimate with --spp 1)\n",
                      n.meanLuminance);
    std::cout << line;
    for (const std::string& f : {a.outHdr, a.out, a.json})
        if (!f.empty() && f != "-") std::cout << "wrote " << f << "\n";
    return 0;
}

const RegisterCommand registerTruth{Command{
    "truth", "Path-traced ground truth of a view (Embree): the renderer's accuracy target", 55,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<TruthArgs>();
        cmd.description(
            "Path-traces one view of a scene as the rasterizer sees it (same camera, GBuffer "
            "materials with textures, sun, sky, punctual and emissive lights, exposure, ACES "
            "tonemap): next-event estimation with MIS, Russian roulette, all cores. Prints the "
            "standard error of the mean luminance, so you can see it converged (halve it with "
            "4x the spp). Cached by input hash in --cache-dir. Deterministic for a seed.");
        addSceneOptions(cmd, a->scene);
        cmd.add_option("--view", a->view, "Named view of the scene (default: its first)");
        cmd.add_option("--camera", a->camera, "Camera px,py,pz,tx,ty,tz[,fovdeg] (overrides --view)");
        cmd.add_option("--width", a->settings.width, "Image width")->capture_default_str();
        cmd.add_option("--height", a->settings.height, "Image height")->capture_default_str();
        cmd.add_option("--spp", a->settings.spp, "Samples per pixel (>= 1; >= 2 for a noise estimate)")
            ->capture_default_str();
        cmd.add_option("--max-depth", a->settings.maxDepth,
                       "Surface vertices with lighting, 1..1024 (1 = direct light only, as the "
                       "renderer's direct pass)")
            ->capture_default_str();
        cmd.add_option("--seed", a->settings.seed, "Random seed")->capture_default_str();
        cmd.add_option("--threads", a->settings.threads, "Threads (0 = all cores; never changes the image)")
            ->capture_default_str();
        cmd.add_option("--exposure", a->exposure, "Exposure for --out (default: the scene's)");
        cmd.add_flag("--mkdir", a->mkdir,
                     "Create missing parent folders of --out, --out-hdr, --json (else a missing "
                     "folder is an error, before any work)");
        cmd.add_option("--out-hdr", a->outHdr, "Linear radiance as PFM (what render --out-hdr writes)")
            ->required();
        cmd.add_option("--out", a->out, "Tonemapped sRGB PNG (the renderer's exposure and ACES fit)");
        a->jsonOption = cmd.add_option("--json", a->json,
                                       "JSON summary (noise, hash, timing) to FILE, or stdout without one")
                            ->expected(0, 1);
        cmd.add_option("--cache-dir", a->cacheDir, "Cache folder (default: the probe cache, ~/.cache/probebench)");
        cmd.add_flag("--no-cache", a->noCache, "Neither read nor write the cache");
        return [a] { return runTruth(*a); };
    },
}};

} // namespace
} // namespace pb::app
