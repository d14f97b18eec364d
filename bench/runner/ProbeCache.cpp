#include "ProbeCache.h"

#include "core/Error.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/bake/Baker.h"
#include "raytrace/EmbreeIsa.h"
#include "probes/store/ProbeFile.h"
#include "probes/Scenario.h"
#include "probes/store/VolumeFile.h"

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

probes::ProbeSet benchProbes(const scene::Scene& s, const std::string& volumes,
                             const std::string& cacheDir, std::string* pathOut,
                             const std::function<void(const std::string&)>& progress) {
    probes::BakeRequest req;
    std::vector<probes::ScenarioSpec> fileScenarios;
    probes::AutoPlacementRequest place;
    if (probes::parseAutoMode(volumes, place.mode)) {
        // As `bake --volumes auto`: adaptive placement stores sparse, auto-uniform dense.
        place.sparse = req.sparse = place.mode == probes::AutoMode::Adaptive;
        // Its lattice search (LatticeShiftSearch.h) measures the bake below: day, 2 bounces.
        place.lighting = probes::resolveScenarios({"day"}, {}, s).front();
        place.bounces = 2;
        req.volumes = probes::placeAutoVolumes(s, place).volumes;
    } else {
        probes::VolumeFile vf = probes::loadVolumeFile(volumes);
        req.volumes = vf.volumes;
        fileScenarios = vf.scenarios;
    }
    req.scenarios = probes::resolveScenarios({"day"}, fileScenarios, s);
    req.settings.raysPerProbe = 128;
    req.settings.bounces = 2;
    req.settings.format = probes::StorageFormat::Rgba16f;
    const std::uint64_t hash = probes::bakeInputHash(s, req);
    // The Embree ISA is part of the name: bakes on two ISAs differ in the last bits, and the
    // gate (which pins SSE2) must not pick up a bench's native bake or the other way round.
    char name[96];
    std::snprintf(name, sizeof name, "-%016llx-%s.pbp", static_cast<unsigned long long>(hash),
                  raytrace::embreeIsa().c_str());
    std::error_code ec;
    fs::create_directories(cacheDir, ec);
    if (ec) throw fileError(cacheDir, "cannot create the probe cache folder: " + ec.message());
    const std::string path = (fs::path(cacheDir) / (s.name + name)).string();
    if (pathOut) *pathOut = path;
    if (auto cached = probes::readCachedProbeFile(path, hash)) return std::move(*cached);
    long long count = 0;
    for (const auto& v : req.volumes)
        count += v.probeCount();
    if (progress)
        progress("baking " + std::to_string(count) + " probes in " +
                 std::to_string(req.volumes.size()) + " volume(s) for '" + s.name +
                 "' (cached as " + path + ")");
    probes::ProbeSet set = probes::bakeProbes(s, req);
    probes::writeProbeFile(path, set);
    return set;
}

} // namespace pb::bench
