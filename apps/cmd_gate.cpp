// probebench gate: the CI regression gate (bench/gate/README.md). Runs the baseline's suite -
// exact counters (GL calls per pass, the cost model's pixels, fetches and bytes, the cache
// model), accuracy against the reference within the baseline's tolerances, timing decided as
// Chromium's Pinpoint does (profile/reference ratios in one run, or this binary against
// another with --against), optionally callgrind instruction counts, and the weak GPUs' shader
// compilers' statistics (exact, keyed by Mesa) - prints a table and exits non-zero on a
// regression. --update rewrites the baseline on purpose.
#include "CommandRegistry.h"
#include "DeviceOptions.h"
#include "GateSuiteOptions.h"
#include "JsonOption.h"
#include "PlatformOptions.h"
#include "ProfileOptions.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/gate/GateEnvironment.h"
#include "bench/gate/GateOutcome.h"
#include "bench/gate/ShaderComparison.h"
#include "bench/gate/PredictionCounters.h"
#include "bench/gate/ShaderCounters.h"
#include "bench/gate_gl/CallgrindFrame.h"
#include "bench/gate_gl/GateWorker.h"
#include "bench/gate_gl/WorkerProcess.h"
#include "bench/runner/BenchContext.h"
#include "bench/runner/PredictionRun.h"
#include "bench/runner/ProbeCache.h"
#include "bench/shaders/MesaShim.h"
#include "bench/shaders_gl/TargetWorkers.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Gzip.h"
#include "core/MachineState.h"
#include "gl/DebugOutput.h"
#include "passes/GiDebugInjection.h"
#include "raytrace/EmbreeIsa.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"
#include "views/WorstCaseView.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace pb::app {
namespace {

namespace fs = std::filesystem;

struct GateArgs {
    JsonOption json;
    std::string baseline, against, cacheDir;
    bool quick = false, update = false, callgrind = false, noTiming = false, noShaders = false;
    bool keepProbes = false; // --update --keep-probes: measure with the committed probe data
    bool requireQuiet = false; // refuse to time on a busy machine
    platform::PlatformOptions platform;
    GateSuiteArgs suite;
};

void gateProgress(const std::string& line) {
    std::fprintf(stderr, "gate: %s\n", line.c_str());
    std::fflush(stderr);
}

std::string probeIdentity(const probes::ProbeSet& set, const std::string& file) {
    // FNV-1a 64 of the probe file, with the offset basis this function always used
    // (1469598103934665603, not FNV's 14695981039346656037 of pb::fnv1a64): every recorded
    // baseline's `probes` and `bake` identities were written with it.
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char b : readFileBytes(file))
        h = (h ^ b) * 1099511628211ull;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%lld probes, %zu volumes, %s, fnv1a %016llx",
                  static_cast<long long>(set.probeCount()), set.volumes.size(),
                  probes::formatName(set.format()), static_cast<unsigned long long>(h));
    return buf;
}

struct GateProbes {
    probes::ProbeSet set;
    std::string file; // what the workers load
};

// This machine's bake of the suite (now.bake), and the probe data every figure is measured
// with (now.probes): the file committed beside the baseline, decompressed into the probe
// cache, so that no counter depends on the CPU that baked (GateEnvironment.h). With --update
// (unless --keep-probes), or for a baseline that has no committed file yet, this machine's bake
// itself (--update then commits it).
GateProbes gateProbes(const GateArgs& a, const gate::GateSuite& s, const scene::Scene& scene,
                      gate::GateRecord& now) {
    const std::string cacheDir = a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir;
    GateProbes out;
    out.set = bench::benchProbes(scene, resolveSuiteVolumes(s.volumes), cacheDir, &out.file,
                                 gateProgress);
    now.bake = probeIdentity(out.set, out.file);
    now.probes = now.bake;
    const std::string committed = gate::committedProbesPath(a.baseline);
    if ((a.update && !a.keepProbes) || !fs::exists(committed)) return out;
    const std::vector<unsigned char> gz = readFileBytes(committed);
    const std::uint64_t h = pb::fnv1a64(gz.data(), gz.size()); // its cache name
    char name[64];
    std::snprintf(name, sizeof name, "gate-committed-%016llx.pbp",
                  static_cast<unsigned long long>(h));
    out.file = (fs::path(cacheDir) / name).string();
    if (!fs::exists(out.file)) {
        const std::vector<unsigned char> bytes = gzipDecompress(gz, committed);
        fs::create_directories(cacheDir);
        writeFileAtomic(out.file, bytes.data(), bytes.size());
    }
    gateProgress("probe data: " + committed + " (committed with the baseline)");
    out.set = probes::readProbeFile(out.file);
    now.probes = probeIdentity(out.set, out.file);
    return out;
}

// The worker command line shared by --against and --callgrind.
std::vector<std::string> workerArgs(const std::string& binary, const gate::GateSuite& s,
                                    const std::string& probesFile, const GateArgs& a) {
    std::vector<std::string> v{binary,       "gate-worker",
                               "--scene",    s.scene,
                               "--probes",   probesFile,
                               "--camera",   s.camera,
                               "--width",    std::to_string(s.width),
                               "--height",   std::to_string(s.height),
                               "--timing",   s.timing.method,
                               "--warmup",   std::to_string(s.timing.warmup),
                               "--platform", a.platform.name};
    if (a.platform.device >= 0) {
        v.push_back("--device");
        v.push_back(std::to_string(a.platform.device));
    }
    return v;
}

void gateCheckGl(gl::DebugOutput& debug, std::uint64_t mark, const std::string& what) {
    const auto errors = debug.errorsSince(mark);
    if (!errors.empty())
        throw Error(what + ": the GL reported " + std::to_string(errors.size()) +
                    " error(s): " + errors.front().text);
}

// --against: this binary and the other one as two workers, every profile. Rows: frame and
// GI passes per profile.
// Seconds a verdict still unknown after the round budget may take (per profile).
double timeBudget(const GateArgs& a, const gate::GateSuite& s) {
    return a.quick ? s.timing.quickTimeBudgetSeconds : s.timing.timeBudgetSeconds;
}

std::vector<gate::GateRow> againstTiming(const GateArgs& a, const gate::GateSuite& s, int budget,
                                         const std::string& probesFile) {
    gate::WorkerProcess cand(workerArgs(gate::selfExecutable(), s, probesFile, a), {},
                             "candidate worker (this binary)");
    gate::WorkerProcess basew(workerArgs(a.against, s, probesFile, a), {},
                              "baseline worker (" + a.against + ")");
    for (gate::WorkerProcess* w : {&cand, &basew})
        gate::checkWorkerHello(w->readLine(), w->label());
    std::vector<gate::GateRow> rows;
    for (const std::string& name : s.profiles) {
        auto say = [&](const std::string& l) { gateProgress("timing " + name + " against: " + l); };
        const gate::SequentialTiming t =
            gate::timeAgainst(basew, cand, name, s.timing, budget, timeBudget(a, s), say);
        for (const gate::TimedQuantity& q : t.quantities)
            rows.push_back(gate::timingRow(
                name, (q.name == "gi" ? "GI passes ms vs " : "frame ms vs ") + a.against,
                q.comparison, "ms", t.rounds, t.budgetReached));
    }
    return rows;
}

// In this process: each profile's frame over the reference's, round by round, against the
// baseline's ratios (recorded into `now` for --update).
std::vector<gate::GateRow> ratioTiming(const GateArgs& a, gate::GateRecord& now,
                                       const gate::GateRecord* base,
                                       std::vector<std::unique_ptr<gate::GateRenderer>>& renderers,
                                       size_t ref, const bench::TimingChoice& timing, bool es,
                                       int budget) {
    const gate::GateSuite& s = now.suite;
    std::vector<gate::GateRow> rows;
    bench::SectionTimer timer(timing, es);
    for (size_t i = 0; i < renderers.size(); ++i) {
        if (i == ref) continue;
        gate::ProfileRecord& rec = now.profiles[i];
        const gate::ProfileRecord* b = base ? base->profile(rec.name) : nullptr;
        const std::vector<double> stored = b ? b->ratioSamples : std::vector<double>{};
        const bool decide = !a.update && stored.size() >= 2;
        auto measure = [&](int round) {
            gate::RoundTimes p, r;
            if (round % 2 == 0) {
                p = gate::timeRound(*renderers[i], timer, s.timing.frames);
                r = gate::timeRound(*renderers[ref], timer, s.timing.frames);
            } else {
                r = gate::timeRound(*renderers[ref], timer, s.timing.frames);
                p = gate::timeRound(*renderers[i], timer, s.timing.frames);
            }
            return std::vector<std::pair<double, double>>{{0.0, p.frameMs / r.frameMs}};
        };
        auto say = [&](const std::string& l) {
            gateProgress("timing " + rec.name + "/reference: " + l);
        };
        if (!decide) say("recording " + std::to_string(budget) + " rounds");
        const gate::SequentialTiming t = gate::runSequential(
            {"ratio"}, measure, {stored}, decide, s.timing, s.timing.ratioThreshold, budget,
            timeBudget(a, s), say);
        rec.ratioSamples = t.quantities[0].candidate;
        if (t.decided)
            rows.push_back(gate::timingRow(rec.name, "frame ratio to " + s.reference,
                                           t.quantities[0].comparison, "x", t.rounds,
                                           t.budgetReached));
        else if (!a.update)
            rows.push_back({rec.name, "timing", "frame ratio to " + s.reference, "-", "measured",
                            gate::RowStatus::Skipped, "the baseline has no ratios (--update)"});
    }
    return rows;
}

// The baseline (absent only with --update) and the suite this run measures.
std::optional<gate::GateRecord> loadBaseline(const GateArgs& a) {
    std::optional<gate::GateRecord> base;
    if (fs::exists(a.baseline))
        base = gate::readGateRecord(a.baseline);
    else if (!a.update)
        throw fileError(a.baseline, "no such baseline (create it with --update)");
    if (!a.against.empty() && !fs::exists(a.against) && a.against.find('/') != std::string::npos)
        throw Error("--against " + a.against + ": no such file");
    return base;
}

// What the counters and accuracy are measured on: the suite's scene and probes, its camera
// (searched once and stored in the suite when it has none), and the GL context's facts.
struct GateSetup {
    scene::Scene scene;
    GateProbes probes;
    scene::View view;
};

GateSetup setUpSuite(const GateArgs& a, gate::GateRecord& now) {
    gate::GateSuite& s = now.suite;
    // Every ray of this run (the bake, the cost model) on one Embree ISA on any x86-64 machine
    // (GateRecord.h; PB_EMBREE_ISA still overrides it, for experiments).
    raytrace::pinEmbreeIsa(gate::kGateEmbreeIsa);
    now.environment.embreeIsa = raytrace::embreeIsa();
    now.environment.cpu = bench::cpuModel();
    SceneArgs sceneArgs;
    sceneArgs.scene = s.scene;
    GateSetup g{loadSceneWithOverrides(sceneArgs), {}, {}};
    g.probes = gateProbes(a, s, g.scene, now);
    if (s.camera.empty()) {
        gateProgress("searching the worst-case view (stored in the baseline)");
        g.view = views::findWorstCaseView(g.scene, g.probes.set, 320,
                                          std::max(16, 320 * s.height / s.width))
                     .view;
        s.camera = cameraSpec(g.view);
    }
    g.view = chooseView(g.scene, "", s.camera);
    return g;
}

// Counters and accuracy: every profile's renderer through the same frame sequence. Returns
// the renderers (the timing rounds reuse them) and the reference's index in them.
std::vector<std::unique_ptr<gate::GateRenderer>> measureProfiles(const gate::GateInputs& in,
                                                                 gate::GateRecord& now,
                                                                 gl::DebugOutput& debug,
                                                                 std::size_t& ref) {
    const gate::GateSuite& s = now.suite;
    const profile::ProfileSearch search = profileSearch();
    gate::ModelScenes scenes(in);
    std::vector<std::unique_ptr<gate::GateRenderer>> renderers;
    ref = 0;
    for (size_t i = 0; i < s.profiles.size(); ++i) {
        gateProgress("counting " + s.profiles[i] + " (" + std::to_string(s.width) + "x" +
                     std::to_string(s.height) + ")");
        const std::uint64_t mark = debug.mark();
        renderers.push_back(
            std::make_unique<gate::GateRenderer>(in, profile::loadProfile(s.profiles[i], search)));
        now.profiles.emplace_back();
        gate::measureCounters(*renderers.back(), in, scenes, now.profiles.back());
        gateCheckGl(debug, mark, "profile " + s.profiles[i]);
        if (s.profiles[i] == s.reference) ref = i;
    }
    for (size_t i = 0; i < renderers.size(); ++i)
        if (i != ref) {
            gateProgress("accuracy of " + s.profiles[i] + " against " + s.reference);
            now.profiles[i].accuracy = gate::measureAccuracy(*renderers[i], *renderers[ref], in);
        }
    return renderers;
}

// --callgrind: one frame per profile under valgrind in a worker, compared with the baseline's
// counts of the same toolchain (into `outcome`, recorded into `now`).
void callgrindStage(const GateArgs& a, const std::string& probesFile, const gl::GlCaps& caps,
                    const gate::GateRecord& base, gate::GateRecord& now,
                    gate::GateOutcome& outcome) {
    const gate::GateSuite& s = now.suite;
    const fs::path dir =
        fs::temp_directory_path() / ("probebench-callgrind-" + std::to_string(::getpid()));
    gateProgress("callgrind: one frame per profile under valgrind, LP_NUM_THREADS=0 (minutes)");
    std::vector<std::string> argv = workerArgs(gate::selfExecutable(), s, probesFile, a);
    argv.push_back("--callgrind-profiles");
    std::string list;
    for (const std::string& p : s.profiles)
        list += (list.empty() ? "" : ",") + p;
    argv.push_back(list);
    const gate::CallgrindRecord cg =
        gate::runCallgrind(argv, caps.version, caps.renderer, dir.string());
    std::error_code ec;
    fs::remove_all(dir, ec);
    now.callgrind = {cg};
    gate::compareCallgrind(base, cg, outcome);
}

// The device model's predictions of the suite (bench/gate/README.md "Shader statistics"): each
// suite profile on the device its [budget] model names, at the suite's size and view, as exact
// counters under "model:<device>" in the shader record. Profiles that name no device are left
// out; a compiler that could not run is a problem like any target's.
void modelStage(const gate::GateSuite& s, const GateSetup& g, gate::ShaderRecord& record,
                std::vector<std::string>& problems) {
    const profile::ProfileSearch search = profileSearch();
    std::vector<profile::PlatformProfile> profiles;
    for (const std::string& name : s.profiles) {
        profile::PlatformProfile p = profile::loadProfile(name, search);
        if (!p.modelDevice.empty()) profiles.push_back(std::move(p));
    }
    if (profiles.empty()) return;
    const std::vector<devicemodel::DeviceSpec> devices = resolvePredictDevices("own", profiles);
    ShaderPlanArgs plan;
    for (const profile::PlatformProfile& p : profiles)
        plan.profiles.push_back(p.name);
    plan.reference = s.reference;
    plan.ablate = false;
    plan.width = s.width;
    plan.height = s.height;
    SceneArgs scene;
    scene.scene = s.scene;
    gateProgress("shaders: the device model of every profile on its own device");
    const shaders::ShaderStatisticsRun run =
        runModelCompilers(devices, plan, scene, g.probes.file, s.camera, 600, g.scene.name,
                          [](const std::string& l) { gateProgress("shaders: model: " + l); });
    for (const std::string& p : shaders::shaderRunProblems(run))
        problems.push_back("model: " + p);
    const bench::BenchPlan benchPlan = bench::makeBenchPlan(
        profiles, profile::loadProfile(s.reference, search), {false, s.width, s.height});
    bench::PredictionRequest req{devices, true, false, [](const std::string& l) { gateProgress(l); }};
    for (const bench::DevicePrediction& d :
         bench::predictDevices(benchPlan, g.scene, g.probes.set, g.view, run, req)) {
        if (!d.error.empty()) {
            problems.push_back("model:" + d.device + ": " + d.error);
            continue;
        }
        record.targets.push_back(gate::predictionRecord(d));
    }
}

// The weak GPUs' compiler statistics (bench/gate/README.md "Shader statistics"): every suite
// profile compiled as itself (no ablation) by each of the suite's shader targets, rendering the
// suite's view with the probe data every other figure is measured with, compared exactly with
// the baseline's record of this Mesa (into `outcome`, recorded into `now`).
void shaderStage(const GateArgs& a, const GateSetup& g, const gate::GateRecord& base,
                 gate::GateRecord& now, gate::GateOutcome& outcome) {
    const gate::GateSuite& s = now.suite;
    if (a.noShaders) {
        outcome.notes.push_back("shaders: not run (--no-shaders)");
        return;
    }
    if (s.shaderTargets.empty()) {
        outcome.notes.push_back("shaders: the suite names no shader targets");
        return;
    }
    shaders::MesaShimInstall install;
    try {
        install = shaders::findMesaShim();
    } catch (const Error& e) {
        gate::shadersNotBuilt(base, e.what(), gate::runningOnCi(), outcome);
        return;
    }
    ShaderRunInputs in;
    for (const std::string& t : s.shaderTargets)
        in.targets += (in.targets.empty() ? "" : ",") + t;
    in.plan.profiles = s.profiles;
    in.plan.reference = s.reference;
    in.plan.ablate = false;
    in.plan.width = s.width;
    in.plan.height = s.height;
    in.scene.scene = s.scene;
    in.probesPath = g.probes.file;
    in.camera = s.camera;
    gateProgress("shaders: every profile on " + in.targets + " (Mesa " + install.mesaVersion +
                 ", drm-shim)");
    const shaders::ShaderStatisticsRun run = runShaderTargets(
        in, g.scene.name, [](const std::string& l) { gateProgress("shaders: " + l); });
    const std::vector<std::string> problems = shaders::shaderRunProblems(run);
    // A partial record would fail every later run on the passes it lacks: record none.
    if (a.update && !problems.empty())
        throw Error("shaders: " + problems.front() +
                    " (baseline not updated; --no-shaders keeps its shader statistics)");
    gate::ShaderRecord record = gate::shaderRecordOf(run, install.drivers, s.profiles);
    std::vector<std::string> all = problems;
    modelStage(s, g, record, all);
    if (a.update && all.size() > problems.size())
        throw Error("shaders: " + all[problems.size()] +
                    " (baseline not updated; --no-shaders keeps its shader statistics)");
    now.shaders = {record};
    gate::compareShaders(base, record, all, outcome, gate::otherMachine(base, now));
}

// --update: the baseline rewritten from this run (callgrind counts of other toolchains kept),
// with the probe data it was measured with committed beside it (already there with
// --keep-probes).
void updateBaseline(const GateArgs& a, const std::optional<gate::GateRecord>& base,
                    const gate::GateRecord& now, const std::string& probesFile) {
    gate::GateRecord out = now;
    if (!a.callgrind && base) out.callgrind = base->callgrind;
    if (a.callgrind && base)
        for (const gate::CallgrindRecord& c : base->callgrind)
            if (!(c.key == now.callgrind.front().key)) out.callgrind.push_back(c);
    // Shader statistics likewise: this Mesa's replaced, other Mesas' kept; all kept when they
    // were not measured (--no-shaders, compilers not built here).
    if (base)
        for (const gate::ShaderRecord& r : base->shaders)
            if (now.shaders.empty() || !(r.key == now.shaders.front().key))
                out.shaders.push_back(r);
    const std::string committed = gate::committedProbesPath(a.baseline);
    if (!a.keepProbes) { // --keep-probes: measured with the committed file, left as it is
        const std::vector<unsigned char> bytes = readFileBytes(probesFile);
        const std::vector<unsigned char> gz = gzipCompress(bytes.data(), bytes.size());
        writeFileAtomic(committed, gz.data(), gz.size());
    }
    gate::writeGateRecord(a.baseline, out);
    std::cout << "updated " << a.baseline << (a.keepProbes ? " (probe data kept: " : " and ")
              << committed << (a.keepProbes ? ")" : "")
              << " (review `git diff` of it and commit it with the change that explains it)\n";
}

int runGate(GateArgs& a) {
    const auto t0 = std::chrono::steady_clock::now();
    if (a.requireQuiet)
        if (const std::string noisy = noisyMachineNow(); !noisy.empty())
            throw Error("--require-quiet: refusing to time: " + noisy);
    if (a.keepProbes && !a.update)
        throw Error("--keep-probes: only with --update (the gate always measures with the "
                    "committed probe data)");
    for (const CLI::Option* o : a.suite.options) // the committed data is of the suite's bake
        if (a.keepProbes && o->count() > 0 &&
            (o->get_name() == "--scene" || o->get_name() == "--volumes"))
            throw Error(o->get_name() + ": not with --keep-probes (another scene or other "
                                        "volumes need their own bake)");
    if (a.keepProbes && !fs::exists(gate::committedProbesPath(a.baseline)))
        throw fileError(gate::committedProbesPath(a.baseline),
                        "no committed probe data to keep (--keep-probes)");
    const std::optional<gate::GateRecord> base = loadBaseline(a);
    gate::GateRecord now;
    now.suite = resolveGateSuite(a.suite, a.update, base ? &base->suite : nullptr,
                                 profile::profileNames(profileSearch()));
    const gate::GateSuite& s = now.suite;
    if (const std::string inj = render::giDebugInjectionSummary(); !inj.empty())
        std::fprintf(stderr, "warning: test-only fault injection active: %s\n", inj.c_str());
    const GateSetup g = setUpSuite(a, now);

    auto platform = platform::createPlatform(a.platform);
    gl::DebugOutput debug;
    const gl::GlCaps caps = gl::queryCaps();
    const bench::TimingChoice timing =
        bench::chooseTiming(s.timing.method, caps, gl::detectDriverQuirks());
    now.recorded = bench::benchContext(*platform, caps);
    now.environment.glRenderer = caps.renderer;
    const gate::GateInputs in{
        &g.scene, &g.probes.set, g.view,         render::defaultFrameSettings(g.scene),
        s.width,  s.height,      s.timing.warmup};
    std::size_t ref = 0;
    auto renderers = measureProfiles(in, now, debug, ref);

    std::vector<gate::GateRow> timingRows;
    const int budget = a.quick ? s.timing.quickMaxRounds : s.timing.maxRounds;
    const MachineState machineBefore = sampleMachineState();
    if (!a.noTiming && !a.against.empty())
        timingRows = againstTiming(a, s, budget, g.probes.file);
    else if (!a.noTiming)
        timingRows =
            ratioTiming(a, now, base ? &*base : nullptr, renderers, ref, timing, caps.es, budget);
    const MachineState machineAfter = sampleMachineState();
    gate::GateOutcome outcome;
    outcome.recording = a.update;
    outcome.undecidedFails = gate::runningOnCi();
    now.recorded["machine"] = toJson(machineBefore, machineAfter);
    if (!a.noTiming)
        if (const std::string noisy = noisyMachineText(machineBefore, machineAfter);
            !noisy.empty())
            outcome.notes.push_back("warning: the machine was not quiet while timing: " + noisy +
                                    "; timing verdicts may stay unknown (--require-quiet "
                                    "refuses to run instead)");
    gate::GateRecord empty;
    empty.suite = s;
    gate::compareRecords(base ? *base : empty, now, outcome);
    outcome.rows.insert(outcome.rows.end(), timingRows.begin(), timingRows.end());
    if (a.noTiming) outcome.notes.push_back("timing: not run (--no-timing)");
    if (a.callgrind)
        callgrindStage(a, g.probes.file, caps, base ? *base : empty, now, outcome);
    else if (base && !base->callgrind.empty())
        outcome.notes.push_back("callgrind: not run (--callgrind runs it)");
    shaderStage(a, g, base ? *base : empty, now, outcome);

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    now.recorded["load_average_end"] = bench::loadAverage();
    now.recorded["seconds"] = seconds;
    now.recorded["quick"] = a.quick;
    outcome.notes.push_back("ran " + std::to_string(int(seconds + 0.5)) + " s, load average " +
                            bench::loadAverage() + (a.quick ? ", --quick" : ""));
    std::cout << gate::gateTable(outcome);
    if (a.json) {
        nlohmann::json j = gate::gateJson(outcome);
        j["measured"] = gate::recordJson(now);
        writeJson(a.json, j.dump(2) + "\n");
    }
    if (a.update) {
        updateBaseline(a, base, now, g.probes.file);
        return 0;
    }
    return outcome.exitCode();
}

const RegisterCommand registerGate{
    {"gate",
     "CI regression gate: exact counters, accuracy, timing (Pinpoint-style) against a baseline", 55,
     [](CLI::App& cmd) {
         auto a = std::make_shared<GateArgs>();
         cmd.add_option("--baseline", a->baseline,
                        "Baseline file (bench/baselines/NAME.json): the suite and what it measured")
             ->required();
         cmd.add_flag("--quick", a->quick,
                      "Smaller timing budget (the baseline's quick_max_rounds): the CI mode; "
                      "counters and accuracy are the same");
         cmd.add_flag("--update", a->update,
                      "Rewrite the baseline with this run's measurements (on purpose: review and "
                      "commit it); exit 0. With the suite options it creates or changes the suite");
         cmd.add_flag("--keep-probes", a->keepProbes,
                      "With --update: measure with the probe data committed beside the baseline "
                      "and keep it, instead of this machine's bake (for a change that moves "
                      "timing or instruction counts but not the bake)");
         cmd.add_option("--against", a->against,
                        "Time this binary against another probebench binary (same profiles, "
                        "interleaved rounds in two worker processes) instead of the "
                        "profile/reference ratios");
         cmd.add_flag("--callgrind", a->callgrind,
                      "Also count instructions of one frame per profile under valgrind callgrind "
                      "(LP_NUM_THREADS=0; gated when the baseline has counts for this Mesa, LLVM, "
                      "compiler and valgrind, skipped otherwise)");
         cmd.add_flag("--no-timing", a->noTiming,
                      "Skip the timing gate (counters and accuracy only)");
         cmd.add_flag("--require-quiet", a->requireQuiet,
                      "Refuse to run (exit 1) when the machine is busy before it: load average "
                      "or other processes' CPU use above half the CPUs, or more than 5% of the "
                      "CPU time stolen by the host");
         cmd.add_flag("--no-shaders", a->noShaders,
                      "Skip the weak GPUs' shader compiler statistics (otherwise measured when "
                      "scripts/mesa-shim.sh has built the compilers; --update then keeps the "
                      "baseline's)");
         a->json.add(cmd, "The verdicts and the measurements");
         cmd.add_option("--cache-dir", a->cacheDir,
                        "Folder of the baked-probe cache (default: ~/.cache/probebench)");
         addPlatformOptions(cmd, a->platform);
         addGateSuiteOptions(cmd, a->suite);
         cmd.footer("Exit codes: 0 pass (or --update done), 1 error, 3 a counter, accuracy, "
                    "instruction-count, shader-statistics or model-vs-GL failure, 4 timing "
                    "regressions only.");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runGate(*a);
         };
     }}};

} // namespace
} // namespace pb::app
