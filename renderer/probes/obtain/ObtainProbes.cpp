#include "ObtainProbes.h"

#include "PlacementCache.h"

#include "core/Error.h"
#include "core/Hash.h"
#include "probes/bake/BakeHash.h"
#include "probes/placement/PlacementKey.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/VolumeFile.h"
#include "raytrace/EmbreeIsa.h"
#include "raytrace/StaticTriangles.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace pb::probes {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The volumes file's volumes, scenarios and placement summary; refused over the budget.
void readVolumesFile(const scene::Scene& s, const BakeOptions& o, PlacedRequest& p,
                     std::vector<ScenarioSpec>& fileScenarios) {
    if (o.spacing > 0.0f) throw Error("--spacing applies to --volumes auto only");
    VolumeFile vf = loadVolumeFile(o.volumes);
    p.request.volumes = vf.volumes;
    fileScenarios = vf.scenarios;
    p.placement.mode = "file";
    p.placement.result.volumes = vf.volumes;
    for (const ProbeVolume& v : vf.volumes)
        p.placement.result.probes += v.probeCount();
    std::vector<std::size_t> kept;
    if (p.placement.sparse) kept = sparseProbeCounts(vf.volumes, raytrace::staticBakeTriangles(s));
    const StorageFormat format = o.settings.format;
    p.placement.result.bytes =
        memoryReport(vf.volumes, format, p.placement.sparse ? &kept : nullptr).total.storedTotal();
    if (o.budgetMib > 0.0 && double(p.placement.result.bytes) > o.budgetMib * 1024.0 * 1024.0)
        throw Error(o.volumes + ": the volumes need " + formatBytes(p.placement.result.bytes) +
                    " as " + formatName(format) + ", over --probe-budget-mib " +
                    std::to_string(o.budgetMib));
}

// Step 1: FILE is up to date by the placement cache, or nothing.
std::optional<ObtainedProbes> upToDateByPlacementCache(const scene::Scene& s, const BakeOptions& o,
                                                       const std::string& file) {
    AutoMode mode;
    if (!parseAutoMode(o.volumes, mode)) return std::nullopt;
    const std::optional<CachedPlacement> cached =
        readPlacementCache(file, autoPlacementKey(s, autoPlacementRequest(o, s, mode)));
    if (!cached) return std::nullopt;
    std::optional<ProbeSet> set;
    try {
        set = readProbeFile(file);
    } catch (const Error&) {
        return std::nullopt; // damaged: placing and baking again says why
    }
    BakeRequest r;
    r.volumes = set->volumes;
    setBakeSettings(o, s, {}, r);
    // As placeRequest sets it: the placement's budget when it had one.
    if (const double b = cached->placement.value("budget_bytes", 0.0); b > 0.0)
        r.freeSpaceBudgetBytes = b;
    if (set->inputHash != cached->inputHash || bakeInputHash(s, r) != set->inputHash)
        return std::nullopt;
    ObtainedProbes out;
    out.set = std::move(*set);
    out.placement = cached->placement;
    return out;
}

void recordPlacement(const scene::Scene& s, const BakeOptions& o, const std::string& file,
                     const nlohmann::json& placement, std::uint64_t inputHash) {
    AutoMode mode;
    if (parseAutoMode(o.volumes, mode))
        writePlacementCache(file, {autoPlacementKey(s, autoPlacementRequest(o, s, mode)),
                                   inputHash, placement});
}

} // namespace

PlacedRequest placeRequest(const scene::Scene& s, const BakeOptions& o, const ObtainHooks& hooks) {
    const auto start = Clock::now();
    PlacedRequest p;
    std::vector<ScenarioSpec> fileScenarios;
    p.placement.sparse = storesSparse(o);
    AutoMode mode;
    if (parseAutoMode(o.volumes, mode)) {
        AutoPlacementRequest req = autoPlacementRequest(o, s, mode);
        req.progress = hooks.placementProgress;
        p.placement.mode = autoModeName(mode);
        p.placement.result = placeAutoVolumes(s, req);
        if (hooks.placementDone) hooks.placementDone();
        if (hooks.note)
            for (const std::string& note : p.placement.result.notes)
                hooks.note(note);
        p.request.volumes = p.placement.result.volumes;
    } else {
        readVolumesFile(s, o, p, fileScenarios);
    }
    setBakeSettings(o, s, fileScenarios, p.request);
    // Automatic placement's budget, the default one included, is what the tiles fill.
    if (p.placement.result.budgetBytes > 0.0)
        p.request.freeSpaceBudgetBytes = p.placement.result.budgetBytes;
    p.placementJson = placementJson(p.placement, p.request.settings.format);
    p.seconds = since(start);
    return p;
}

ObtainedProbes obtainProbes(const scene::Scene& s, const BakeOptions& o, const std::string& file,
                            Reuse reuse, const ObtainHooks& hooks) {
    if (reuse == Reuse::PlacementAndBake)
        if (std::optional<ObtainedProbes> cached = upToDateByPlacementCache(s, o, file))
            return std::move(*cached);
    const PlacedRequest placed = placeRequest(s, o, hooks);
    if (hooks.placed) hooks.placed(placed);
    ObtainedProbes out;
    out.placement = placed.placementJson;
    out.placedThisRun = true;
    out.placementSeconds = placed.seconds;
    const std::uint64_t hash = bakeInputHash(s, placed.request);
    if (reuse != Reuse::Nothing) {
        std::string why;
        if (std::optional<ProbeSet> cached = readCachedProbeFile(file, hash, &why)) {
            recordPlacement(s, o, file, out.placement, hash);
            out.set = std::move(*cached);
            return out;
        }
        if (why.rfind("unusable", 0) == 0 && hooks.note)
            hooks.note("re-baking, the old file is " + why);
    }
    if (hooks.bakeStarts) hooks.bakeStarts(placed);
    out.set = bakeProbes(s, placed.request, &out.stats, hooks.bakeProgress);
    out.baked = true;
    const auto writeStart = Clock::now();
    writeProbeFile(file, out.set);
    recordPlacement(s, o, file, out.placement, out.set.inputHash);
    out.writeSeconds = since(writeStart);
    return out;
}

std::string probeCachePath(const scene::Scene& s, const BakeOptions& o, const std::string& cacheDir) {
    std::uint64_t key = 0;
    AutoMode mode;
    if (parseAutoMode(o.volumes, mode)) {
        // The placement key covers the scene and everything placing depends on; the settings'
        // hash (no volumes yet) the rest of the bake.
        BakeRequest settingsOnly;
        setBakeSettings(o, s, {}, settingsOnly);
        Hasher h;
        h.pod(autoPlacementKey(s, autoPlacementRequest(o, s, mode)));
        h.pod(bakeInputHash(s, settingsOnly));
        key = h.value();
    } else {
        // A volumes file is read, not placed: the bake's own input hash names it.
        PlacedRequest p;
        std::vector<ScenarioSpec> fileScenarios;
        p.placement.sparse = storesSparse(o);
        readVolumesFile(s, o, p, fileScenarios);
        setBakeSettings(o, s, fileScenarios, p.request);
        key = bakeInputHash(s, p.request);
    }
    char name[96];
    std::snprintf(name, sizeof name, "-%016llx-%s.pbp", static_cast<unsigned long long>(key),
                  raytrace::embreeIsa().c_str());
    std::error_code ec;
    fs::create_directories(cacheDir, ec);
    if (ec) throw fileError(cacheDir, "cannot create the probe cache folder: " + ec.message());
    return (fs::path(cacheDir) / (s.name + name)).string();
}

} // namespace pb::probes
