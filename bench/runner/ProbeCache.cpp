#include "ProbeCache.h"

#include "probes/obtain/ObtainProbes.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace pb::bench {

namespace fs = std::filesystem;

std::string defaultProbeCacheDir() {
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
        return (fs::path(x) / "probebench").string();
    if (const char* h = std::getenv("HOME"); h && *h)
        return (fs::path(h) / ".cache" / "probebench").string();
    return ".probebench-cache";
}

namespace {
std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
}
} // namespace

probes::BakeOptions benchBakeOptions(const std::string& volumes) {
    probes::BakeOptions o;
    o.volumes = volumes;
    o.settings.raysPerProbe = kBenchRaysPerProbe;
    o.settings.noiseTarget = kBenchNoiseTarget;
    return o;
}

std::string benchBakeFlags() {
    char text[64];
    std::snprintf(text, sizeof text, "--rays %d --noise-target %g", kBenchRaysPerProbe,
                  double(kBenchNoiseTarget));
    return text;
}

probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& volumes,
                             const std::string& cacheDir, std::string* pathOut,
                             const std::function<void(const std::string&)>& progress,
                             int* passes) {
    const probes::BakeOptions o = benchBakeOptions(volumes);
    const std::string path = probes::probeCachePath(s, o, cacheDir);
    if (pathOut) *pathOut = path;
    probes::ObtainHooks hooks;
    if (progress) {
        hooks.placed = [&](const probes::PlacedRequest& p) {
            if (p.placement.mode != "file")
                progress("placed " + std::to_string(p.placement.result.probes) + " probes in " +
                         std::to_string(p.request.volumes.size()) + " volume(s) for '" + s.name +
                         "' (--volumes " + volumes + ", " + seconds(p.seconds) + ")");
        };
        hooks.bakeStarts = [&](const probes::PlacedRequest& p) {
            long long count = 0;
            for (const auto& v : p.request.volumes)
                count += v.probeCount();
            progress("baking " + std::to_string(count) + " probes in " +
                     std::to_string(p.request.volumes.size()) + " volume(s) for '" + s.name +
                     "' (cached as " + path + ")");
        };
        hooks.note = [&](const std::string& note) { progress("note: " + note); };
    }
    probes::ObtainedProbes got = probes::obtainProbes(s, o, path, probes::Reuse::PlacementAndBake, hooks);
    if (passes) *passes = got.baked && !got.stats.passes.empty() ? got.stats.passes.front() : 0;
    return std::move(got.set);
}

} // namespace pb::bench
