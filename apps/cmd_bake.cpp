// probebench bake: probe volumes -> Embree bake -> probe data file (cached by input hash).
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "OutputPaths.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "probes/obtain/BakeReport.h"
#include "probes/obtain/ObtainProbes.h"
#include "probes/store/ProbeFileParts.h"
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
    int rays = 256, threads = 0;
    std::string bounces = "auto";
    int emitterSamples = probes::BakeSettings().emitterSamples;
    int litSamples = probes::BakeSettings().litSamples;
    float noiseTarget = probes::BakeSettings().noiseTarget;
    std::vector<std::string> scenarios;
    std::string format = "rgba16f";
    std::uint64_t seed = 1;
    std::string out;
    JsonOption json;
    bool mkdir = false; // create missing parent folders of the outputs
    bool force = false, noRelocate = false, sparse = false, dense = false;
    bool noLatticeSearch = false;
    std::string freeSpace = "ranked";   // --free-space (issue 18)
    bool freeSpaceIrradiance = false;   // --free-space-irradiance: --free-space all
    const CLI::Option *freeSpaceOption = nullptr, *freeSpaceIrradianceOption = nullptr;
    float backfaceThreshold = 0.25f;
    std::string split, part; // --split scenario --part I/N: one part of a split bake
};

// "I/N" of --part.
std::pair<int, int> parsePart(const std::string& text) {
    int part = -1, parts = 0;
    char slash = 0, rest = 0;
    if (std::sscanf(text.c_str(), "%d %c %d %c", &part, &slash, &parts, &rest) != 3 ||
        slash != '/')
        throw UsageError("--part: expected I/N, e.g. 0/2 (got '" + text + "')");
    return {part, parts};
}

// --bounces: 'auto' (0, until converged) or a count in [1, 64].
int parseBounces(const std::string& text) {
    if (text == "auto") return 0;
    int n = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d %c", &n, &rest) != 1 || n < 1 || n > 64)
        throw UsageError("--bounces: expected auto or a count in [1, 64] (got '" + text + "')");
    return n;
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
        throw UsageError("--split: expected scenario (got '" + a.split + "')");
    if (a.part.empty()) throw Error("--split: needs --part I/N (this machine's part)");
    if (a.out.empty()) throw Error("--split: needs --out (the part file to write)");
    auto [part, parts] = parsePart(a.part);
    return scenarioSplit(scenarios, part, parts);
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

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// What the probes sparse storage leaves out keep (--free-space, --free-space-irradiance).
FreeSpace freeSpaceOf(const BakeArgs& a) {
    if (a.freeSpaceIrradiance) return FreeSpace::Irradiance;
    FreeSpace f = FreeSpace::Ranked;
    if (!parseFreeSpace(a.freeSpace, f))
        throw UsageError("--free-space: '" + a.freeSpace + "' is not one of stand-ins, ranked, all");
    return f;
}

// The options every command that needs probes shares (probes/obtain/BakeOptions.h).
BakeOptions bakeOptions(const BakeArgs& a) {
    BakeOptions o;
    o.volumes = a.volumes;
    o.spacing = a.spacing;
    o.autoLevels = a.autoLevels;
    o.autoMaxChildren = a.autoMaxChildren;
    o.budgetMib = a.budgetMib;
    o.latticeSearch = !a.noLatticeSearch;
    o.scenarios = a.scenarios;
    o.settings.raysPerProbe = a.rays;
    o.settings.bounces = parseBounces(a.bounces);
    o.settings.emitterSamples = a.emitterSamples;
    o.settings.litSamples = a.litSamples;
    o.settings.noiseTarget = a.noiseTarget;
    o.settings.seed = a.seed;
    o.settings.format = parseStorageFormat(a.format);
    o.settings.relocate = !a.noRelocate;
    o.settings.backfaceThreshold = a.backfaceThreshold;
    o.threads = a.threads;
    o.sparse = a.sparse;
    o.dense = a.dense;
    o.freeSpace = freeSpaceOf(a);
    return o;
}

// What obtaining probes shows while it works: placement steps, notes, the placement line and
// the bake's header and progress bar.
ObtainHooks bakeHooks(const BakeArgs& a, const scene::Scene& s, Progress& progress) {
    ObtainHooks h;
    h.placementProgress = placementProgress;
    h.placementDone = endPlacementProgress;
    h.note = [](const std::string& note) { std::cerr << "note: " << note << "\n"; };
    h.placed = [&a](const PlacedRequest& p) {
        if (!a.json) std::cout << placementText(p.placementJson, true) << "\n";
    };
    h.bakeStarts = [&a, &s](const PlacedRequest& p) {
        if (a.json) return;
        long long probes = 0;
        for (const ProbeVolume& v : p.request.volumes)
            probes += v.probeCount();
        const BakeRequest& req = p.request;
        std::cout << "bake: scene '" << s.name << "', " << req.volumes.size() << " volume(s), "
                  << probes << " probes, " << req.settings.raysPerProbe << " rays, "
                  << (req.settings.bounces > 0 ? std::to_string(req.settings.bounces) + " bounce(s)"
                                               : std::string("bounces until converged"))
                  << ", " << req.scenarios.size()
                  << " scenario(s), " << formatName(req.settings.format) << std::endl;
    };
    h.bakeProgress = [&progress](const BakeProgress& p) { progress(p); };
    return h;
}

void printReport(const BakeArgs& a, const BakeReport& r) {
    if (a.json)
        writeJson(a.json, bakeReportJson(r).dump(2) + "\n");
    else
        std::cout << bakeReportText(r);
    // Exit 0 still: the probes are usable, only noisier than asked (issue 42 item 3). JSON on
    // stdout carries it (noise.probes_above_target, above_target_region) and stays the only output.
    if (const std::string w = noiseTargetWarning(r); !w.empty() && !a.json.toStdout())
        std::cerr << "warning: " << w << "\n";
}

// --write-volumes without --out: only the placement.
int writeVolumesOnly(const BakeArgs& a, const PlacedRequest& placed) {
    if (a.json)
        writeJson(a.json, nlohmann::json{{"volumes_file", a.writeVolumes},
                                         {"placement", placed.placementJson}}
                              .dump(2) + "\n");
    else
        std::cout << placementText(placed.placementJson, true) << "\nwrote " << a.writeVolumes
                  << "\n";
    return 0;
}

void writeVolumes(const BakeArgs& a, const scene::Scene& s, const std::vector<ProbeVolume>& v) {
    writeVolumeFile(a.writeVolumes, v,
                    "probe volumes for scene '" + s.name +
                        "', written by probebench bake --write-volumes\n"
                        "edit freely; bake with --volumes FILE (add --sparse for the storage "
                        "--volumes auto uses; renderer/probes/README.md)");
}

// --split scenario --part I/N: one block of the scenarios into a part file, never a cache hit.
int bakePart(const BakeArgs& a, const scene::Scene& s, const BakeOptions& o, CommandSeconds& t,
             std::chrono::steady_clock::time_point start) {
    Progress progress;
    ObtainHooks hooks = bakeHooks(a, s, progress);
    PlacedRequest placed = placeRequest(s, o, hooks);
    t.placement = placed.seconds;
    if (hooks.placed) hooks.placed(placed);
    placed.request.onlyScenarios = splitScenarios(a, placed.request.scenarios.size());
    hooks.bakeStarts(placed);
    BakeStats stats;
    ProbeFilePart part;
    part.set = bakeProbes(s, placed.request, &stats, hooks.bakeProgress);
    progress.done();
    const auto writeStart = std::chrono::steady_clock::now();
    const auto [index, parts] = parsePart(a.part);
    part.part = std::uint32_t(index);
    part.parts = std::uint32_t(parts);
    part.totalScenarios = std::uint32_t(placed.request.scenarios.size());
    for (std::size_t i : placed.request.onlyScenarios)
        part.scenarios.push_back(std::uint32_t(i));
    writeProbeFilePart(a.out, part);
    t.write = seconds(writeStart);
    t.command = seconds(start);
    printReport(a, {a.out, placed.placementJson, true, false, part.set, &stats,
                    freeSpaceProbes(part.set, s), t});
    return 0;
}

int runBake(const BakeArgs& a) {
    const auto start = std::chrono::steady_clock::now();
    if (a.out.empty() && a.writeVolumes.empty())
        throw Error("--out is required (the probe file to write), or --write-volumes alone to "
                    "only place volumes");
    if (!(a.budgetMib >= 0.0) || !std::isfinite(a.budgetMib))
        throw UsageError("--probe-budget-mib: must be a positive number");
    if (a.sparse && a.dense) throw Error("--dense: excludes --sparse (pick one storage)");
    for (const CLI::Option* o : {a.freeSpaceOption, a.freeSpaceIrradianceOption})
        if (o && o->count() > 0 && !storesSparse(bakeOptions(a)))
            throw Error(o->get_name() + ": needs sparse storage (--volumes auto without "
                        "--dense, or --sparse)");
    if (a.freeSpaceIrradiance && a.freeSpaceOption && a.freeSpaceOption->count() > 0 &&
        a.freeSpace != "all")
        throw Error("--free-space-irradiance: is --free-space all, not " + a.freeSpace);
    bakeOptions(a); // a bad --free-space or --format is refused before the placement runs
    AutoMode mode = AutoMode::Uniform;
    const bool adaptive = parseAutoMode(a.volumes, mode) && mode == AutoMode::Adaptive;
    for (const CLI::Option* o : {a.levelsOption, a.childrenOption})
        if (o && o->count() > 0 && !adaptive)
            throw Error(o->get_name() + " applies to --volumes auto only (not '" + a.volumes +
                        "')");
    if (a.noLatticeSearch && !adaptive)
        throw Error("--no-lattice-search applies to --volumes auto only (not '" + a.volumes + "')");
    // Said before the placement and the bake (minutes on a large scene), not after them
    // (OutputPaths.h: the rule every command follows).
    if (!a.writeVolumes.empty()) prepareOutputParent("--write-volumes", a.writeVolumes, a.mkdir);
    if (!a.out.empty()) prepareOutputParent("--out", a.out, a.mkdir);
    if (!a.json.file().empty())
        prepareOutputParent("--json", a.json.file(), a.mkdir);
    const BakeOptions o = bakeOptions(a);
    scene::Scene s = loadSceneWithOverrides(a.scene);
    CommandSeconds t;
    t.load = seconds(start);
    // A wrong split is refused before the placement runs (seconds to minutes) and prints.
    if (!a.split.empty() || !a.part.empty()) {
        splitScenarios(a, scenarioCountBeforePlacement(o, s));
        return bakePart(a, s, o, t, start);
    }
    if (a.out.empty()) {
        Progress progress;
        const PlacedRequest placed = placeRequest(s, o, bakeHooks(a, s, progress));
        writeVolumes(a, s, placed.request.volumes);
        return writeVolumesOnly(a, placed);
    }
    Progress progress;
    ObtainHooks hooks = bakeHooks(a, s, progress);
    // --write-volumes writes the volumes placed this run (the probe file may still be reused).
    const Reuse reuse = a.force                  ? Reuse::Nothing
                        : !a.writeVolumes.empty() ? Reuse::BakeOnly
                                                  : Reuse::PlacementAndBake;
    ObtainedProbes got = obtainProbes(s, o, a.out, reuse, hooks);
    progress.done();
    if (!a.writeVolumes.empty()) writeVolumes(a, s, got.set.volumes);
    if (!got.placedThisRun && !a.json) std::cout << placementText(got.placement, false) << "\n";
    t.placement = got.placementSeconds;
    t.write = got.writeSeconds;
    t.command = seconds(start);
    printReport(a, {a.out, got.placement, got.placedThisRun, !got.baked, got.set,
                    got.baked ? &got.stats : nullptr, freeSpaceProbes(got.set, s), t});
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
        cmd.add_option("--bounces", a->bounces,
                       "Bounce passes: 'auto' runs them until the last one adds under 1% of the "
                       "light (all the bounces; later passes trace fewer rays), N in [1, 64] "
                       "exactly N (1 = direct light at the hits)")
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
                     "irradiance error (over 2% less; up to 22 one-scenario bakes with 32 rays; "
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
                   "picks a coarser spacing (studies/findings/mid-air-options.md \"Mid-air options\")")
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
        cmd.add_flag("--mkdir", a->mkdir,
                     "Create missing parent folders of --out, --write-volumes, --json (else a "
                     "missing folder is an error, before any work)");
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
