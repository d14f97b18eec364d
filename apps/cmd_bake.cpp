// probebench bake: probe volumes -> Embree bake -> probe data file (cached by input hash).
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "PlacementCache.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/placement/PlacementKey.h"
#include "probes/bake/Baker.h"
#include "probes/store/MemoryReport.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeCounts.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/ProbeFileParts.h"
#include "raytrace/RayScene.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "probes/store/VolumeFile.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace pb::app {
namespace {

using namespace pb::probes;
namespace fs = std::filesystem;

struct BakeArgs {
    SceneArgs scene;
    std::string volumes = "auto";
    float spacing = 0.0f;
    int autoLevels = 2, autoMaxChildren = 4;
    double budgetMib = 0.0;
    std::string writeVolumes;
    const CLI::Option *levelsOption = nullptr, *childrenOption = nullptr; // given or not
    int rays = 256, bounces = 2, threads = 0;
    int emitterSamples = probes::BakeSettings().emitterSamples;
    int litSamples = probes::BakeSettings().litSamples;
    float noiseTarget = probes::BakeSettings().noiseTarget;
    std::vector<std::string> scenarios;
    std::string format = "rgba16f";
    std::uint64_t seed = 1;
    std::string out;
    JsonOption json;
    bool force = false, noRelocate = false, sparse = false, dense = false;
    bool noLatticeSearch = false;
    std::string freeSpace = "ranked";   // --free-space (issue 18)
    bool freeSpaceIrradiance = false;   // --free-space-irradiance: --free-space all
    const CLI::Option *freeSpaceOption = nullptr, *freeSpaceIrradianceOption = nullptr;
    float backfaceThreshold = 0.25f;
    std::string split, part; // --split scenario --part I/N: one part of a split bake
};

// Wall seconds of the whole command, by phase (issue 17: the summary's time once covered only
// the tracing, 1.17 s of a 16.8 s bake). `bake` is BakeStats::seconds (BVH, tracing, encoding).
struct CommandTimes {
    using Clock = std::chrono::steady_clock;
    Clock::time_point start = Clock::now();
    double load = 0.0, placement = 0.0, write = 0.0;
    static double since(Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    }
};

// "I/N" of --part.
std::pair<int, int> parsePart(const std::string& text) {
    int part = -1, parts = 0;
    char slash = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d %c %d %c", &part, &slash, &parts, &rest) != 3 ||
        slash != '/')
        throw Error("--part: expected I/N, e.g. 0/2 (got '" + text + "')");
    return {part, parts};
}

// --split: which scenarios of the request this part bakes; empty = not split.
std::vector<std::size_t> splitScenarios(const BakeArgs& a, std::size_t scenarios) {
    if (a.split.empty()) {
        if (!a.part.empty()) throw Error("--part: needs --split scenario");
        return {};
    }
    if (a.split == "volume")
        throw Error("--split volume: not supported: a bounce pass looks up every volume's "
                    "previous pass and nested rings blend across volumes, so one volume's probes "
                    "cannot be baked apart from the others'; use --split scenario");
    if (a.split != "scenario")
        throw Error("--split: expected scenario (got '" + a.split + "')");
    if (a.part.empty()) throw Error("--split: needs --part I/N (this machine's part)");
    if (a.out.empty()) throw Error("--split: needs --out (the part file to write)");
    auto [part, parts] = parsePart(a.part);
    return scenarioSplit(scenarios, part, parts);
}

// Sparse storage (SparseStorage.h): `--volumes auto` stores sparse unless --dense (the issue's
// automatic placement stores only the probes a surface reads); auto-uniform and volumes files
// store dense unless --sparse.
bool storesSparse(const BakeArgs& a) {
    AutoMode mode = AutoMode::Uniform;
    const bool adaptive = parseAutoMode(a.volumes, mode) && mode == AutoMode::Adaptive;
    return a.sparse || (adaptive && !a.dense);
}

// A bar on a terminal, one line per finished stage otherwise (logs, CI).
class Progress {
public:
    Progress() : tty_(::isatty(::fileno(stderr)) != 0) {}
    void operator()(const BakeProgress& p) {
        if (p.stage != stage_) finishStage();
        stage_ = p.stage;
        if (!tty_ || p.total == 0) return;
        const int width = 30;
        int filled = int(double(p.done) / double(p.total) * width);
        std::fprintf(stderr, "\r[%-*s] %3d%%  %-24s", width,
                     std::string(size_t(filled), '#').c_str(),
                     int(100.0 * double(p.done) / double(p.total)), stage_.c_str());
        std::fflush(stderr);
    }
    void finishStage() {
        if (stage_.empty()) return;
        if (!tty_) std::fprintf(stderr, "bake: %s done\n", stage_.c_str());
        stage_.clear();
    }
    void done() {
        finishStage();
        if (tty_) std::fprintf(stderr, "\r%-70s\r", "");
    }

private:
    bool tty_;
    std::string stage_;
};

// Automatic placement's steps (AutoPlacementRequest::progress): on a terminal one line that
// updates, otherwise one line per lattice-search estimate and every 10th placement, so a log
// shows where the seconds before the bake went.
void placementProgress(const std::string& stage, int done, int total) {
    static const bool tty = ::isatty(::fileno(stderr)) != 0;
    if (tty) {
        if (total > 0)
            std::fprintf(stderr, "\r%-70s\rbake: %s %d/%d", "", stage.c_str(), done, total);
        else
            std::fprintf(stderr, "\r%-70s\rbake: %s %d", "", stage.c_str(), done);
        std::fflush(stderr);
        return;
    }
    if (total > 0)
        std::fprintf(stderr, "bake: %s %d/%d\n", stage.c_str(), done, total);
    else if (done == 1 || done % 10 == 0)
        std::fprintf(stderr, "bake: %s %d\n", stage.c_str(), done);
}

void endPlacementProgress() {
    if (::isatty(::fileno(stderr)) != 0) std::fprintf(stderr, "\r%-70s\r", "");
}

// Nesting depth of each volume (0 = root).
std::vector<int> volumeDepths(const std::vector<ProbeVolume>& volumes) {
    std::vector<int> parents = validateVolumes(volumes, "placement"), depth(volumes.size(), 0);
    for (size_t i = 0; i < volumes.size(); ++i)
        for (int p = parents[i]; p >= 0; p = parents[size_t(p)])
            ++depth[i];
    return depth;
}

// What automatic placement chose, for people ("placement: ...") and for --json.
struct PlacementInfo {
    std::string mode;    // "adaptive", "uniform" or "file"
    bool sparse = false; // stored sparse: result.bytes counts what is stored
    AutoPlacementResult result;
};

// What `bake` prints of the placement: placed this run (placementJson of the result), or
// read from the placement cache (PlacementCache.h) when the probe file is up to date.
struct PlacementSummary {
    nlohmann::json json;
    bool placedThisRun = true;
};

nlohmann::json placementJson(const PlacementInfo& p, StorageFormat format) {
    std::vector<int> depth = volumeDepths(p.result.volumes);
    nlohmann::json tiers = nlohmann::json::array();
    for (size_t i = 0; i < p.result.volumes.size(); ++i) {
        if (size_t(depth[i]) >= tiers.size())
            tiers.push_back({{"volumes", 0}, {"probes", 0}, {"spacing", 0.0}});
        auto& t = tiers[size_t(depth[i])];
        const ProbeVolume& v = p.result.volumes[i];
        glm::vec3 c = v.cellSize();
        t["volumes"] = t["volumes"].get<int>() + 1;
        t["probes"] = t["probes"].get<long long>() + v.probeCount();
        t["spacing"] = std::max(c.x, std::max(c.y, c.z));
    }
    nlohmann::json j{{"mode", p.mode},
                     {"tiers", tiers},
                     {"probes", p.result.probes},
                     {"bytes", p.result.bytes},
                     {"budget_bytes", p.result.budgetBytes},
                     {"default_budget", p.result.defaultBudget},
                     {"format", formatName(format)},
                     {"storage", p.sparse ? "sparse" : "dense"},
                     {"notes", p.result.notes}};
    if (p.result.latticeSearched) {
        const LatticeShift& l = p.result.latticeShift;
        j["lattice_search"] = {{"shift_cells", {l.cells.x, l.cells.y, l.cells.z}},
                               {"estimated_error_before", l.errorBefore},
                               {"estimated_error_after", l.errorAfter},
                               {"trials", l.trials},
                               {"seconds", p.result.latticeSearchSeconds}};
    }
    if (p.mode == "adaptive") {
        j["corner_rays"] = p.result.stats.rays;
        j["cells_tested"] = p.result.stats.cellsTested;
        j["cells_near_surfaces"] = p.result.stats.cellsNear;
        j["placements"] = p.result.placements;
    }
    return j;
}

// One line from the placement's JSON, so a cached placement prints as a fresh one does.
std::string placementText(const PlacementSummary& summary) {
    const nlohmann::json& j = summary.json;
    std::ostringstream s;
    int volumes = 0;
    for (const auto& tier : j["tiers"])
        volumes += tier["volumes"].get<int>();
    s << "placement: " << j["mode"].get<std::string>() << ", " << volumes << " volume(s)";
    for (size_t t = 0; t < j["tiers"].size(); ++t) {
        const auto& tier = j["tiers"][t];
        s << (t == 0 ? "; outer " : "; tier " + std::to_string(t) + " ")
          << tier["volumes"].get<int>() << " x spacing " << tier["spacing"].get<double>() << " ("
          << tier["probes"].get<long long>() << " probes)";
    }
    const double budget = j["budget_bytes"].get<double>();
    s << "; " << formatBytes(j["bytes"].get<std::size_t>()) << " as "
      << j["format"].get<std::string>() << (j["storage"] == "sparse" ? " stored sparse" : "");
    if (j["default_budget"].get<bool>())
        s << " (default budget: the default uniform grid's " << formatBytes(std::size_t(budget))
          << ")";
    else if (budget > 0.0)
        s << " (budget " << formatBytes(std::size_t(budget)) << ")";
    if (j.contains("corner_rays"))
        s << "; " << j["corner_rays"].get<long long>() << " corner rays, "
          << j["placements"].get<int>() << " placement(s)";
    if (j.contains("lattice_search")) {
        const auto& l = j["lattice_search"];
        s.precision(3);
        s << "; lattice search: shift (" << l["shift_cells"][0].get<double>() << ", "
          << l["shift_cells"][1].get<double>() << ", " << l["shift_cells"][2].get<double>()
          << ") cells, estimated error " << l["estimated_error_before"].get<double>() << " -> "
          << l["estimated_error_after"].get<double>() << ", " << l["trials"].get<int>()
          << " trial bakes in " << l["seconds"].get<double>() << " s";
    }
    if (!summary.placedThisRun) s << " (when baked; not placed again: the placement cache matches)";
    return s.str();
}

// What the probes sparse storage leaves out keep (--free-space, --free-space-irradiance).
FreeSpace freeSpaceOf(const BakeArgs& a) {
    if (a.freeSpaceIrradiance) return FreeSpace::Irradiance;
    FreeSpace f = FreeSpace::Ranked;
    if (!parseFreeSpace(a.freeSpace, f))
        throw Error("--free-space: '" + a.freeSpace + "' is not one of stand-ins, ranked, all");
    return f;
}

// The automatic placement request of these options (its key decides the placement cache).
AutoPlacementRequest autoPlacementRequest(const BakeArgs& a, const scene::Scene& s,
                                          AutoMode mode) {
    AutoPlacementRequest req;
    req.mode = mode;
    req.adaptive.spacing = a.spacing;
    req.adaptive.levels = a.autoLevels;
    req.adaptive.maxChildren = a.autoMaxChildren;
    req.adaptive.threads = a.threads;
    req.budgetBytes = a.budgetMib * 1024.0 * 1024.0;
    req.format = parseStorageFormat(a.format);
    req.sparse = storesSparse(a);
    req.freeSpace = req.sparse ? freeSpaceOf(a) : FreeSpace::StandIns;
    // The lattice search bakes trials as this bake will be baked, under its first scenario.
    req.latticeSearch = !a.noLatticeSearch;
    req.lighting = resolveScenarios(a.scenarios, {}, s).front();
    req.bounces = a.bounces;
    return req;
}

// Everything of the request but the volumes.
void setBakeSettings(const BakeArgs& a, const scene::Scene& s,
                     const std::vector<ScenarioSpec>& fileScenarios, BakeRequest& r) {
    r.scenarios = resolveScenarios(a.scenarios, fileScenarios, s);
    r.settings.raysPerProbe = a.rays;
    r.settings.bounces = a.bounces;
    r.settings.emitterSamples = a.emitterSamples;
    r.settings.litSamples = a.litSamples;
    r.settings.noiseTarget = a.noiseTarget;
    r.settings.seed = a.seed;
    r.settings.format = parseStorageFormat(a.format);
    r.settings.relocate = !a.noRelocate;
    r.settings.backfaceThreshold = a.backfaceThreshold;
    r.threads = a.threads;
    r.sparse = storesSparse(a);
    r.freeSpace = r.sparse ? freeSpaceOf(a) : FreeSpace::StandIns;
    // Ranked tiles fill the budget; automatic placement sets its own (the default one too).
    r.freeSpaceBudgetBytes = a.budgetMib * 1024.0 * 1024.0;
}

// The number of scenarios the request will hold, without placing: a volumes file may add its
// own scenarios, automatic placement adds none.
std::size_t scenarioCountBeforePlacement(const BakeArgs& a, const scene::Scene& s) {
    AutoMode mode;
    if (parseAutoMode(a.volumes, mode)) return resolveScenarios(a.scenarios, {}, s).size();
    return resolveScenarios(a.scenarios, loadVolumeFile(a.volumes).scenarios, s).size();
}

BakeRequest buildRequest(const BakeArgs& a, const scene::Scene& s, PlacementInfo& placement) {
    BakeRequest r;
    std::vector<ScenarioSpec> fileScenarios;
    const StorageFormat format = parseStorageFormat(a.format);
    const bool sparse = placement.sparse = storesSparse(a);
    AutoMode mode;
    if (parseAutoMode(a.volumes, mode)) {
        AutoPlacementRequest req = autoPlacementRequest(a, s, mode);
        req.progress = placementProgress;
        placement.mode = autoModeName(mode);
        placement.result = placeAutoVolumes(s, req);
        endPlacementProgress();
        for (const std::string& note : placement.result.notes)
            std::cerr << "note: " << note << "\n";
        r.volumes = placement.result.volumes;
    } else {
        if (a.spacing > 0.0f) throw Error("--spacing applies to --volumes auto only");
        VolumeFile vf = loadVolumeFile(a.volumes);
        r.volumes = vf.volumes;
        fileScenarios = vf.scenarios;
        placement.mode = "file";
        placement.result.volumes = vf.volumes;
        for (const ProbeVolume& v : vf.volumes)
            placement.result.probes += v.probeCount();
        std::vector<std::size_t> kept;
        if (sparse) kept = sparseProbeCounts(vf.volumes, raytrace::staticBakeTriangles(s));
        placement.result.bytes =
            memoryReport(vf.volumes, format, sparse ? &kept : nullptr).total.storedTotal();
        if (a.budgetMib > 0.0 && double(placement.result.bytes) > a.budgetMib * 1024.0 * 1024.0)
            throw Error(a.volumes + ": the volumes need " + formatBytes(placement.result.bytes) +
                        " as " + formatName(format) + ", over --probe-budget-mib " +
                        std::to_string(a.budgetMib));
    }
    setBakeSettings(a, s, fileScenarios, r);
    // Automatic placement's budget, the default one included, is what the tiles fill.
    if (placement.result.budgetBytes > 0.0) r.freeSpaceBudgetBytes = placement.result.budgetBytes;
    return r;
}

// The probe file is up to date without placing: the placement cache has this request's key,
// and the file's volumes with the other options hash to the file's own input hash (the one the
// cache recorded). Nothing when anything differs or fails to read: then bake places as ever.
std::optional<std::pair<ProbeSet, nlohmann::json>> upToDateByPlacementCache(
    const BakeArgs& a, const scene::Scene& s) {
    AutoMode mode;
    if (a.force || a.out.empty() || !a.writeVolumes.empty() || !parseAutoMode(a.volumes, mode))
        return std::nullopt;
    const std::optional<CachedPlacement> cached =
        readPlacementCache(a.out, autoPlacementKey(s, autoPlacementRequest(a, s, mode)));
    if (!cached) return std::nullopt;
    std::optional<ProbeSet> set;
    try {
        set = readProbeFile(a.out);
    } catch (const Error&) {
        return std::nullopt; // damaged: the normal path re-bakes it and says why
    }
    BakeRequest r;
    r.volumes = set->volumes;
    setBakeSettings(a, s, {}, r);
    // As buildRequest sets it: the placement's budget when it had one.
    if (const double b = cached->placement.value("budget_bytes", 0.0); b > 0.0)
        r.freeSpaceBudgetBytes = b;
    if (set->inputHash != cached->inputHash || bakeInputHash(s, r) != set->inputHash)
        return std::nullopt;
    return std::make_pair(std::move(*set), cached->placement);
}

// A count, or null when the file cannot tell (ProbeCounts.h).
nlohmann::json countJson(const std::optional<std::size_t>& n) {
    return n ? nlohmann::json(*n) : nlohmann::json(nullptr);
}

nlohmann::json volumesJson(const ProbeSet& set, const std::vector<ProbeCounts>& counts) {
    nlohmann::json out = nlohmann::json::array();
    for (size_t v = 0; v < set.volumes.size(); ++v) {
        const ProbeVolume& vol = set.volumes[v];
        std::size_t moved = 0;
        for (const ProbeState& p : set.states[v])
            moved += p.offset != glm::vec3(0.0f) ? 1 : 0;
        out.push_back({{"name", vol.name},
                       {"parent", vol.parent},
                       {"counts", {vol.counts.x, vol.counts.y, vol.counts.z}},
                       {"center", {vol.center.x, vol.center.y, vol.center.z}},
                       {"half_extents", {vol.halfExtents.x, vol.halfExtents.y, vol.halfExtents.z}},
                       {"probes", vol.probeCount()},
                       {"stored", counts[v].stored},
                       {"absent", countJson(counts[v].absent)},
                       {"invalid", countJson(counts[v].invalid)},
                       {"relocated", moved}});
    }
    return out;
}

// "probes: N in V volume(s), ..." : stored / absent / invalid (ProbeCounts.h).
// `irradianceOnly`: how many absent probes kept their irradiance (--free-space).
// volumeProbeCounts always knows absent and invalid (the bake's count, or the states).
std::string probeCountsText(const ProbeCounts& c, std::size_t volumes,
                            std::size_t irradianceOnly) {
    std::ostringstream s;
    s << "probes: " << c.probes << " in " << volumes << " volume(s), ";
    if (c.notStored() == 0)
        s << "all stored, " << *c.invalid << " invalid (inside geometry)";
    else
        s << c.stored << " stored, " << *c.absent
          << (irradianceOnly == 0 ? " absent (not stored: no surface nearby), "
              : irradianceOnly == *c.absent
                  ? " absent (no surface nearby: irradiance only, no visibility), "
                  : " absent (no surface nearby; " + std::to_string(irradianceOnly) +
                        " of them keep their irradiance, no visibility), ")
          << *c.invalid << " invalid (inside geometry, not stored)";
    return s.str();
}

// Per scenario, the irradiance's storage scale (probes/StorageScale.h; 1 when in range).
float scenarioScale(const ProbeSet& set, std::size_t s) {
    return s < set.irradiance.size() && !set.irradiance[s].empty()
               ? set.irradiance[s].front().storageScale
               : 1.0f;
}

// The stored probes only the free-space lattice keeps, for the summary; a dense set has none,
// and is not classified against the scene's triangles (an up-to-date run stays quick).
std::size_t freeSpaceProbes(const ProbeSet& set, const scene::Scene& s) {
    if (set.storedCount() == set.probeCount()) return 0;
    return freeSpaceOnlyProbes(set, raytrace::staticBakeTriangles(s));
}

// The bytes the irradiance-only probes' tiles add (one scenario, in the file's format): what
// `with` (the set's memory report) counts beyond the stored tiles. 0 when there are none.
std::size_t irradianceOnlyBytes(const ProbeSet& set, const MemoryReport& with) {
    if (with.total.irradianceOnlyProbes == 0) return 0;
    std::vector<std::size_t> stored;
    for (const auto& states : set.states) stored.push_back(probes::storedCount(states));
    const MemoryReport without = memoryReport(set.volumes, set.format(), &stored);
    return with.total.stored.total() - std::min(with.total.stored.total(),
                                                without.total.stored.total());
}

// The end of the summary's "free space:" line: what the absent probes keep (--free-space).
std::string freeSpaceText(std::size_t tiles, const std::string& tileBytes, std::size_t standIns,
                          const BakeStats* st) {
    if (tiles == 0) return "absent probes are read as their nearest stored one";
    std::ostringstream s;
    s << tiles << " absent probes keep their irradiance (" << tileBytes << ", no visibility)";
    if (standIns == 0) return s.str();
    s << ": the ones whose nearest stored probe is furthest from their own light; the other "
      << standIns << " are read as it";
    if (st && st->freeSpaceCandidates > 0) {
        s.precision(3);
        s << " (largest difference left " << 100.0 * st->freeSpaceWorstLeft << "%)";
    }
    return s.str();
}

// `freeSpace`: the stored probes only the free-space lattice keeps (freeSpaceOnlyProbes), the
// cost of lighting the air between surfaces (issue 18), with the irradiance-only probes.
void printSummary(const BakeArgs& a, const PlacementSummary& placement, const ProbeSet& set,
                  const BakeStats* st, bool upToDate, std::size_t freeSpace,
                  const CommandTimes& times) {
    const double commandSeconds = CommandTimes::since(times.start);
    const double searchSeconds =
        placement.placedThisRun ? placement.json.value("lattice_search", nlohmann::json::object())
                                      .value("seconds", 0.0)
                                : 0.0;
    MemoryReport mem = memoryReport(set);
    const std::size_t freeSpaceBytes = freeSpace * bytesPerProbe(set.format()).total();
    const std::size_t irradianceOnly = irradianceOnlyBytes(set, mem);
    // Absent probes lookups read their nearest stored probe for.
    std::size_t standIns = 0;
    for (const auto& states : set.states)
        for (const ProbeState& p : states)
            standIns += fillable(p, set.settings.backfaceThreshold) ? 1 : 0;
    const std::vector<ProbeCounts> counts =
        volumeProbeCounts(set, st ? &st->invalidPerVolume : nullptr);
    const ProbeCounts total = totalProbeCounts(counts);
    if (a.json) {
        nlohmann::json j{{"file", a.out},
                         {"placement", placement.json},
                         {"placed_this_run", placement.placedThisRun},
                         {"up_to_date", upToDate},
                         {"input_hash", set.inputHash},
                         {"format", formatName(set.format())},
                         {"rays_per_probe", set.settings.raysPerProbe},
                         {"bounces", set.settings.bounces},
                         {"seed", set.settings.seed},
                         {"probes", total.probes},
                         {"stored_probes", total.stored},
                         {"absent_probes", countJson(total.absent)},
                         {"invalid_probes", countJson(total.invalid)},
                         {"volumes", volumesJson(set, counts)},
                         {"memory", memoryReportJson(mem)}};
        if (set.storedCount() < set.probeCount())
            j["free_space"] = {{"lattice_probes", freeSpace},
                               {"lattice_bytes", freeSpaceBytes},
                               {"lattice_step", kFreeSpaceLatticeStep},
                               {"irradiance_only_probes", mem.total.irradianceOnlyProbes},
                               {"irradiance_only_bytes", irradianceOnly},
                               {"stand_in_probes", standIns}};
        if (st && st->freeSpaceCandidates > 0) {
            j["free_space"]["tile_candidates"] = st->freeSpaceCandidates;
            j["free_space"]["worst_stand_in_difference"] = st->freeSpaceWorstLeft;
        }
        nlohmann::json sc = nlohmann::json::array();
        nlohmann::json scales = nlohmann::json::object();
        for (std::size_t i = 0; i < set.scenarios.size(); ++i) {
            sc.push_back(set.scenarios[i].name);
            scales[set.scenarios[i].name] = scenarioScale(set, i);
        }
        j["scenarios"] = sc;
        j["storage_scales"] = scales;
        if (st) {
            double rays = double(st->primaryRays + st->shadowRays);
            j["relocated_probes"] = st->relocatedProbes;
            j["rays"] = st->primaryRays;
            j["shadow_rays"] = st->shadowRays;
            j["seconds"] = st->seconds;
            j["command_seconds"] = commandSeconds;
            j["load_seconds"] = times.load;
            j["placement_seconds"] = times.placement;
            j["lattice_search_seconds"] = searchSeconds;
            j["write_seconds"] = times.write;
            j["bvh_seconds"] = st->buildSeconds;
            j["trace_seconds"] = st->traceSeconds;
            j["encode_seconds"] = st->quantiseSeconds;
            j["rays_per_second"] = st->seconds > 0 ? rays / st->seconds : 0.0;
            j["threads"] = st->threads;
            j["triangles"] = st->triangles;
            j["noise"] = {{"target", set.settings.noiseTarget},
                          {"emitter_samples", set.settings.emitterSamples},
                          {"lit_samples", set.settings.litSamples},
                          {"mean_relative_se", st->noiseMean},
                          {"p95_relative_se", st->noiseP95},
                          {"probe_passes", st->tracedProbePasses},
                          {"probe_passes_with_more_rounds", st->noisyProbePasses},
                          {"probe_passes_above_target", st->probePassesAboveTarget},
                          {"extra_round_rays", st->extraRoundRays}};
            nlohmann::json q = nlohmann::json::array();
            for (const auto& e : st->quantisation)
                q.push_back({{"volume", e.volume},
                             {"texture", e.texture},
                             {"max_relative_error", e.maxRelative},
                             {"mean_relative_error", e.meanRelative}});
            j["quantisation"] = q;
        }
        writeJson(a.json, j.dump(2) + "\n");
        return;
    }
    if (upToDate) std::cout << a.out << ": up to date (input hash matches; --force re-bakes)\n";
    std::cout << probeCountsText(total, set.volumes.size(), mem.total.irradianceOnlyProbes);
    if (st) std::cout << ", " << st->relocatedProbes << " relocated";
    std::cout << "\n";
    if (st) {
        double rays = double(st->primaryRays + st->shadowRays);
        std::printf("rays: %llu (%d per probe per pass) + %llu shadow rays, %d thread(s), %zu "
                    "triangles\n",
                    (unsigned long long)st->primaryRays, set.settings.raysPerProbe,
                    (unsigned long long)st->shadowRays, st->threads, st->triangles);
        std::printf("noise: mean %.2f%%, p95 %.2f%% relative standard error of a probe's "
                    "irradiance",
                    100 * st->noiseMean, 100 * st->noiseP95);
        if (set.settings.noiseTarget > 0)
            std::printf(" (target %.3g%%: %zu of %zu probe passes took more rounds, +%llu rays; "
                        "%zu stayed above after %d rounds)",
                        100 * set.settings.noiseTarget, st->noisyProbePasses,
                        st->tracedProbePasses, (unsigned long long)st->extraRoundRays,
                        st->probePassesAboveTarget, probes::kMaxNoiseRounds);
        std::printf("\n");
        std::printf("time: %.2f s in all: scene %.2f s, placement %.2f s", commandSeconds,
                    times.load, times.placement);
        if (searchSeconds > 0) std::printf(" (lattice search %.2f s)", searchSeconds);
        std::printf(", bake %.2f s (BVH %.2f s, tracing %.2f s, %s encoding %.2f s), write "
                    "%.2f s; %.2f M rays/s in the bake\n",
                    st->seconds, st->buildSeconds, st->traceSeconds, formatName(set.format()),
                    st->quantiseSeconds, times.write,
                    st->seconds > 0 ? rays / st->seconds * 1e-6 : 0.0);
        double worst = 0.0;
        for (const auto& e : st->quantisation)
            worst = std::max(worst, e.maxRelative);
        if (set.format() == StorageFormat::Bc6h)
            for (const auto& e : st->quantisation)
                std::printf("bc6h error %-12s %-20s max %.4f mean %.5f (relative)\n",
                            e.volume.c_str(), e.texture.c_str(), e.maxRelative, e.meanRelative);
        else
            std::printf("%s quantisation: max relative error %.2g\n", formatName(set.format()),
                        worst);
    }
    for (std::size_t i = 0; i < set.scenarios.size(); ++i)
        if (scenarioScale(set, i) != 1.0f)
            std::printf("scenario %s: irradiance stored x2^%d (outside %s's comfortable range)\n",
                        set.scenarios[i].name.c_str(), std::ilogb(scenarioScale(set, i)),
                        formatName(set.format()));
    std::cout << "memory (one scenario resident): " << formatBytes(mem.total.uncompressed.total())
              << " uncompressed, " << formatBytes(mem.total.bc6h.total()) << " bc6h; file holds "
              << set.scenarios.size() << " scenario(s) as " << formatName(set.format()) << "\n";
    if (set.storedCount() < set.probeCount())
        std::cout << "sparse storage: " << set.storedCount() << " of " << set.probeCount()
                  << " grid probes stored, " << formatBytes(mem.total.storedTotal()) << " as "
                  << formatName(set.format()) << " with the indirection\n"
                  << "free space: " << freeSpace << " of the stored probes ("
                  << formatBytes(freeSpaceBytes) << ") are kept only as the free-space lattice "
                  << "(every " << kFreeSpaceLatticeStep << "nd probe per axis); "
                  << freeSpaceText(mem.total.irradianceOnlyProbes, formatBytes(irradianceOnly),
                                   standIns, st)
                  << "\n";
    else
        std::cout << "sparse-storage candidates: " << mem.total.sparse.far
                  << " probe(s) far from every surface, " << mem.total.sparse.invalid
                  << " inside geometry (stored; sparse storage drops what no surface reads)\n";
    if (!upToDate) std::cout << "wrote " << a.out << "\n";
}

int runBake(const BakeArgs& a) {
    CommandTimes times;
    if (a.out.empty() && a.writeVolumes.empty())
        throw Error("--out is required (the probe file to write), or --write-volumes alone to "
                    "only place volumes");
    if (!(a.budgetMib >= 0.0) || !std::isfinite(a.budgetMib))
        throw Error("--probe-budget-mib: must be a positive number");
    if (a.sparse && a.dense) throw Error("--dense: excludes --sparse (pick one storage)");
    for (const CLI::Option* o : {a.freeSpaceOption, a.freeSpaceIrradianceOption})
        if (o && o->count() > 0 && !storesSparse(a))
            throw Error(o->get_name() + ": needs sparse storage (--volumes auto without "
                        "--dense, or --sparse)");
    if (a.freeSpaceIrradiance && a.freeSpaceOption && a.freeSpaceOption->count() > 0 &&
        a.freeSpace != "all")
        throw Error("--free-space-irradiance: is --free-space all, not " + a.freeSpace);
    if (storesSparse(a)) freeSpaceOf(a); // a bad name is refused before the placement runs
    AutoMode mode = AutoMode::Uniform;
    const bool adaptive = parseAutoMode(a.volumes, mode) && mode == AutoMode::Adaptive;
    for (const CLI::Option* o : {a.levelsOption, a.childrenOption})
        if (o && o->count() > 0 && !adaptive)
            throw Error(o->get_name() + " applies to --volumes auto only (not '" + a.volumes +
                        "')");
    if (a.noLatticeSearch && !adaptive)
        throw Error("--no-lattice-search applies to --volumes auto only (not '" + a.volumes + "')");
    if (!a.writeVolumes.empty()) {
        fs::path parent = fs::path(a.writeVolumes).parent_path();
        if (!parent.empty() && !fs::is_directory(parent))
            throw Error("--write-volumes " + a.writeVolumes + ": folder does not exist");
    }
    // Said before the placement and the bake (minutes on a large scene), not after them.
    if (!a.out.empty()) {
        const fs::path parent = fs::path(a.out).parent_path();
        if (!parent.empty() && !fs::is_directory(parent))
            throw Error("--out " + a.out + ": folder '" + parent.string() + "' does not exist");
    }
    scene::Scene s = loadSceneWithOverrides(a.scene);
    times.load = CommandTimes::since(times.start);
    // A wrong split is refused before the placement runs (seconds to minutes) and prints.
    if (!a.split.empty() || !a.part.empty()) splitScenarios(a, scenarioCountBeforePlacement(a, s));
    // A part file is never up to date: a split part is always baked.
    if (auto cached = a.split.empty() ? upToDateByPlacementCache(a, s) : std::nullopt) {
        const PlacementSummary summary{cached->second, false};
        if (!a.json) std::cout << placementText(summary) << "\n";
        printSummary(a, summary, cached->first, nullptr, true,
                     freeSpaceProbes(cached->first, s), times);
        return 0;
    }
    PlacementInfo placement;
    const auto placementStart = CommandTimes::Clock::now();
    BakeRequest req = buildRequest(a, s, placement);
    times.placement = CommandTimes::since(placementStart);
    const PlacementSummary summary{placementJson(placement, req.settings.format), true};
    // Recorded once the probe file for this placement exists (baked, or found up to date).
    const auto recordPlacement = [&](std::uint64_t inputHash) {
        AutoMode mode;
        if (parseAutoMode(a.volumes, mode))
            writePlacementCache(a.out, {autoPlacementKey(s, autoPlacementRequest(a, s, mode)),
                                        inputHash, summary.json});
    };
    if (!a.writeVolumes.empty()) {
        writeVolumeFile(a.writeVolumes, req.volumes,
                        "probe volumes for scene '" + s.name +
                            "', written by probebench bake --write-volumes\n"
                            "edit freely; bake with --volumes FILE (add --sparse for the storage "
                            "--volumes auto uses; renderer/probes/README.md)");
        if (a.out.empty()) {
            if (a.json)
                writeJson(a.json, nlohmann::json{{"volumes_file", a.writeVolumes},
                                            {"placement",
                                             placementJson(placement, req.settings.format)}}
                                 .dump(2) + "\n");
            else
                std::cout << placementText(summary) << "\nwrote "
                          << a.writeVolumes << "\n";
            return 0;
        }
    }
    req.onlyScenarios = splitScenarios(a, req.scenarios.size());
    const std::uint64_t hash = bakeInputHash(s, req);
    if (!a.force && a.split.empty()) {
        std::string why;
        if (std::optional<ProbeSet> cached = readCachedProbeFile(a.out, hash, &why)) {
            if (!a.json) std::cout << placementText(summary) << "\n";
            recordPlacement(hash);
            printSummary(a, summary, *cached, nullptr, true,
                         freeSpaceProbes(*cached, s), times);
            return 0;
        }
        if (why.rfind("unusable", 0) == 0)
            std::cerr << "note: re-baking, the old file is " << why << "\n";
    }
    long long probes = 0;
    for (const ProbeVolume& v : req.volumes)
        probes += v.probeCount();
    if (!a.json) std::cout << placementText(summary) << "\n";
    if (!a.json)
        std::cout << "bake: scene '" << s.name << "', " << req.volumes.size() << " volume(s), "
                  << probes << " probes, " << req.settings.raysPerProbe << " rays, "
                  << req.settings.bounces << " bounce(s), " << req.scenarios.size()
                  << " scenario(s), " << formatName(req.settings.format) << std::endl;
    Progress progress;
    BakeStats stats;
    ProbeSet set = bakeProbes(s, req, &stats, [&](const BakeProgress& p) { progress(p); });
    progress.done();
    const auto writeStart = CommandTimes::Clock::now();
    if (!a.split.empty()) {
        ProbeFilePart part;
        const auto [index, parts] = parsePart(a.part);
        part.part = std::uint32_t(index);
        part.parts = std::uint32_t(parts);
        part.totalScenarios = std::uint32_t(req.scenarios.size());
        for (std::size_t i : req.onlyScenarios)
            part.scenarios.push_back(std::uint32_t(i));
        part.set = std::move(set);
        writeProbeFilePart(a.out, part);
        set = std::move(part.set);
    } else {
        writeProbeFile(a.out, set);
        recordPlacement(set.inputHash);
    }
    times.write = CommandTimes::since(writeStart);
    printSummary(a, summary, set, &stats, false, freeSpaceProbes(set, s),
                 times);
    return 0;
}

const RegisterCommand registerBake{{
    "bake",
    "Bake DDGI probes (irradiance + visibility) for a scene with Embree into a probe file",
    30,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<BakeArgs>();
        addSceneOptions(cmd, a->scene);
        cmd.add_option("--volumes", a->volumes,
                       "Probe volumes: a TOML file (see renderer/probes/README.md), 'auto' (a "
                       "coarse outer volume over the static bounds plus nested finer volumes "
                       "near surfaces, stored sparse unless --dense) or 'auto-uniform' (one "
                       "volume fitted to the static bounds)")
            ->capture_default_str();
        cmd.add_option("--spacing", a->spacing,
                       "Probe spacing, scene units: for auto the finest (innermost child) "
                       "spacing, the outer volume uses spacing * 2^levels (default: outer "
                       "volume about 512 probes); for auto-uniform the grid spacing (default: "
                       "about 4096 probes)");
        a->levelsOption =
            cmd.add_option("--auto-levels", a->autoLevels,
                           "Nesting tiers below the outer volume for --volumes auto, 1..4 (each "
                           "halves the spacing)")
                ->capture_default_str();
        a->childrenOption =
            cmd.add_option("--auto-max-children", a->autoMaxChildren,
                           "Most child volumes per parent volume for --volumes auto")
                ->capture_default_str();
        cmd.add_option("--probe-budget-mib", a->budgetMib,
                       "Probe memory budget in MiB (one scenario resident, in --format): auto "
                       "placement coarsens until it fits and says so; a volumes file over it is "
                       "an error (default: none; auto without --spacing uses the default uniform "
                       "grid's memory)");
        cmd.add_option("--write-volumes", a->writeVolumes,
                       "Write the volumes used as an editable volumes file (TOML) that "
                       "--volumes reads back to the same placement; without --out nothing is "
                       "baked");
        cmd.add_option("--rays", a->rays, "Rays per probe per pass (spherical Fibonacci)")
            ->capture_default_str();
        cmd.add_option("--bounces", a->bounces, "Bounce passes (1 = direct light at the hits)")
            ->capture_default_str();
        cmd.add_option("--scenario", a->scenarios,
                       "Lighting scenario to bake, repeatable: day, night or a [[scenario]] of the "
                       "volumes file (default: day)");
        cmd.add_option("--format", a->format, "Storage: rgba16f, rgba32f or bc6h")
            ->capture_default_str();
        cmd.add_option("--seed", a->seed, "Seed of the radiance passes' ray rotations and emitter samples (where probes sit and which are valid does not depend on it)")
            ->capture_default_str();
        cmd.add_option("--noise-target", a->noiseTarget,
                       "Converged bake: probes whose irradiance noise (relative standard error) "
                       "is above this after a pass get more rounds of rays, up to 16x; in (0, 1), "
                       "0 = one round")
            ->capture_default_str();
        cmd.add_option("--emitter-samples", a->emitterSamples,
                       "Points sampled on the emissive triangles per probe and pass, weighted "
                       "against the rays by MIS (0: emitters found by the rays alone)")
            ->capture_default_str();
        cmd.add_option("--lit-samples", a->litSamples,
                       "Points sampled on the surfaces the sun and punctual lights light "
                       "directly, per probe and pass, weighted against the rays by MIS (light "
                       "seen through a doorway; 0: found by the rays alone)")
            ->capture_default_str();
        cmd.add_option("--threads", a->threads,
                       "Worker threads (0 = all cores; never changes "
                       "the result)")
            ->capture_default_str();
        cmd.add_option("--backface-threshold", a->backfaceThreshold,
                       "Back-face hit ratio above which a probe is invalid")
            ->capture_default_str();
        cmd.add_flag("--no-relocate", a->noRelocate, "Do not move probes out of geometry");
        cmd.add_flag("--no-lattice-search", a->noLatticeSearch,
                     "--volumes auto under a budget (the default one too) ends by shifting its "
                     "lattice by up to 0.4 of a cell per axis where trial bakes measure less "
                     "irradiance error (over 2% less; up to 25 one-scenario bakes with 32 rays; "
                     "renderer/probes/placement/LatticeShiftSearch.h); this keeps the lattice as placed "
                     "(auto only)");
        cmd.add_flag("--sparse", a->sparse,
                     "Sparse storage: store only valid probes at the corners of grid cells that "
                     "static surface passes through, and a coarse lattice through free space "
                     "(every 2nd probe per axis); absent probes read as their nearest stored "
                     "one (no surface's lighting changes; dynamic objects in the air stay "
                     "lit); --probe-budget-mib then counts "
                     "only what is stored, so auto placement fits a finer spacing. The default "
                     "for --volumes auto; for auto-uniform and volumes files add it");
        a->freeSpaceOption =
            cmd.add_option(
                   "--free-space", a->freeSpace,
                   "With sparse storage, what the valid probes it leaves out (no surface "
                   "nearby) keep. ranked: the ones whose stand-in (the nearest stored probe, "
                   "which lookups read instead) is furthest from their own light keep their "
                   "irradiance tile (a third of a probe's bytes, no visibility), as many as "
                   "the memory budget allows: what auto placement leaves of its budget (it is "
                   "placed again to leave 5% when that costs at most 5% of its spacing; "
                   "without a budget they add 5% of the whole). stand-ins: none do. "
                   "all: every one does, and the budget counts them all, so auto placement "
                   "picks a coarser spacing (bench/README.md \"Mid-air options\")")
                ->capture_default_str();
        a->freeSpaceIrradianceOption = cmd.add_flag(
            "--free-space-irradiance", a->freeSpaceIrradiance, "Same as --free-space all");
        cmd.add_flag("--dense", a->dense,
                     "Dense storage: store every grid probe (the default for auto-uniform and "
                     "volumes files; with --volumes auto it turns sparse storage off)");
        cmd.add_option("--out", a->out,
                       "Probe file to write (reused when its inputs match); required unless "
                       "--write-volumes is given");
        cmd.add_flag("--force", a->force, "Bake even when --out is up to date");
        cmd.add_option("--split", a->split,
                       "Bake one part of a split bake: 'scenario' (each part bakes a block of "
                       "the --scenario list; every part runs the whole geometry pass). --out is "
                       "then a part file that 'probebench bake-merge' joins with the others into "
                       "the file one bake writes, byte for byte (never a cache hit)");
        cmd.add_option("--part", a->part, "With --split: this part, I/N (0 <= I < N)");
        a->json.add(cmd, "The summary");
        return [a] { return runBake(*a); };
    },
}};

} // namespace
} // namespace pb::app
