// probebench tune: searches the switch space for the most accurate configuration that fits a
// frame-time budget on THIS device (or, with --timing model:NAME, on device NAME as the device
// model predicts it: bench/devicemodel) and a GI memory budget (probe textures under gi.volume_lod +
// GI targets), measuring every candidate with the bench runner (pb_bench: interleaved rounds,
// FLIP against the reference profile on the same frame); prints the Pareto front (time,
// memory, FLIP), writes the winner as a profile inheriting the base, loads it back and
// re-measures it. The search itself is bench/tune (GL-free); this file wires it to GL.
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "DeviceOptions.h"
#include "JsonOption.h"
#include "ProbeOptions.h"
#include "PlatformOptions.h"
#include "ProfileOptions.h"
#include "profile/PlatformProfile.h"
#include "SceneOptions.h"
#include "ShaderTargetOptions.h"
#include "bench/runner/PredictionRun.h"
#include "bench/shaders/MesaShim.h"
#include "bench/runner/BenchContext.h"
#include "bench/runner/BenchTruth.h"
#include "bench/runner/ProbeCache.h"
#include "bench/runner/SessionRunner.h"
#include "bench/tune/BudgetCheck.h"
#include "bench/tune/TuneReport.h"
#include "bench/tune/TunedProfile.h"
#include "bench/tune/VolumeLodLevels.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "frame/FrameRenderer.h"
#include "frame/GiMemory.h"
#include "gl/DebugOutput.h"
#include "passes/DynamicObjects.h"
#include "probes/store/VolumeRanksFile.h"
#include "views/WorstCaseView.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>

namespace pb::app {
namespace {

namespace fs = std::filesystem;

struct TuneArgs {
    bool mkdir = false; // --mkdir: create --out's and --json's folders
    bool force = false; // --probes baked for another scene
    SceneArgs scene;
    platform::PlatformOptions platform;
    JsonOption json;
    std::string base = "reference", reference = "reference", out, probes, volumes = "auto",
                cacheDir, view, camera, timing = "auto";
    std::vector<std::string> search, sets;
    double budgetMs = 0, budgetMiB = 0, ppd = 67.0;
    bool acceptOverBudget = false; // write a profile that re-measures over --budget-ms
    int width = 0, height = 0, frames = 2, rounds = 3, warmup = 2, maxExhaustive = 24,
        maxPasses = 2;
    bool truth = false; // --truth: minimise FLIP against the path-traced truth instead
    int truthSpp = 64;
};

void tuneProgress(const std::string& line) {
    std::fprintf(stderr, "tune: %s\n", line.c_str());
    std::fflush(stderr);
}

void validateTune(const TuneArgs& a) {
    if (a.truthSpp < 1) throw UsageError("--truth-spp must be at least 1");
    if (!(a.budgetMs > 0 && a.budgetMs <= 1000)) throw UsageError("--budget-ms must be in (0, 1000]");
    if (!(a.budgetMiB > 0 && a.budgetMiB <= 65536))
        throw UsageError("--budget-mib must be in (0, 65536]");
    if (fs::path(a.out).extension() != ".toml")
        throw Error("--out " + a.out + ": not a .toml file");
    if ((a.width > 0) != (a.height > 0)) throw Error("--width and --height go together");
    if (a.width != 0 && (a.width < 16 || a.height < 16 || a.width > 16384 || a.height > 16384))
        throw UsageError("--width/--height must be in 16..16384");
    if (a.frames < 1 || a.rounds < 1 || a.warmup < 1)
        throw UsageError("--frames, --rounds and --warmup must be at least 1");
    if (a.maxExhaustive < 1 || a.maxPasses < 1)
        throw UsageError("--max-exhaustive and --max-passes must be at least 1");
    if (!a.view.empty() && !a.camera.empty()) throw Error("give --view or --camera, not both");
    if (a.timing.rfind("model:", 0) == 0) {
        // Said before the bake: the device, and whether the compilers are built.
        resolvePredictDevices(a.timing.substr(6), {});
        shaders::findMesaShim();
    }
}

// `--timing model:NAME`: the device the device model predicts for; empty for a measured timing.
std::string modelDeviceName(const TuneArgs& a) {
    return a.timing.rfind("model:", 0) == 0 ? a.timing.substr(6) : "";
}

// What `inherit` in the written file says for the base: its name, or its path from the file.
std::string inheritRef(const TuneArgs& a, const profile::PlatformProfile& base) {
    if (!profile::looksLikeProfilePath(a.base)) return base.name;
    const fs::path from = fs::absolute(fs::path(a.out)).parent_path();
    return fs::relative(fs::absolute(base.file), from).string();
}

// Everything the measurements need; GL is created on the first measurement, so a search that
// fails on memory alone renders nothing.
class Measurer {
public:
    Measurer(const TuneArgs& a, const scene::Scene& s, const probes::ProbeSet& set,
             const profile::PlatformProfile& base, const profile::PlatformProfile& reference,
             int width, int height)
        : a_(a), scene_(s), set_(set), base_(base), reference_(reference), width_(width),
          height_(height) {}

    std::vector<bench::TuneMeasurement> operator()(const std::vector<profile::Profile>& batch) {
        start();
        bench::BenchPlan plan;
        plan.reference = reference_;
        bench::Session session;
        session.profile = base_;
        session.profile.name = "tune";
        session.width = width_;
        session.height = height_;
        for (size_t i = 0; i < batch.size(); ++i)
            session.variants.push_back({"candidate " + std::to_string(i + 1),
                                        bench::candidateLabel(batch[i], base_.switches),
                                        bench::VariantRole::Profile, "", batch[i]});
        session.variants.push_back(
            {"reference", "reference", bench::VariantRole::Reference, "", reference_.switches});
        session.referenceVariant = int(batch.size());
        plan.sessions.push_back(session);
        bench::RunnerInputs in{&scene_, &set_, view_, render::defaultFrameSettings(scene_),
                               debug_.get()};
        if (a_.truth) in.truth = &truth_;
        const std::vector<bench::SessionResult> got = bench::runBenchPlan(plan, in, options_);
        const bench::SessionResult& r = got.front();
        const std::vector<double> predicted = predict(batch);
        std::vector<bench::TuneMeasurement> out;
        for (size_t i = 0; i < batch.size(); ++i) {
            const bench::VariantResult& v = r.variants[i];
            bench::TuneMeasurement m;
            m.ok = v.ok() && v.accuracy.measured && (!a_.truth || v.vsTruth.measured);
            m.error = !v.ok() ? v.error
                      : m.ok  ? ""
                              : "the reference did not run: " + r.reference().error;
            m.frameMs = predicted.empty() ? v.frameMs.median : predicted[i];
            if (!predicted.empty() && !std::isfinite(predicted[i])) {
                m.ok = false;
                m.error = "the device model could not predict it";
            }
            // The objective: FLIP against the reference, or with --truth against the truth.
            m.flip = a_.truth ? v.vsTruth.flipMean : v.accuracy.flipMean;
            m.relativeMseGi = v.accuracy.relativeMseGi;
            out.push_back(m);
        }
        return out;
    }

    const scene::View& view() const { return view_; }
    const nlohmann::json& context() const { return context_; }
    const nlohmann::json& truthInfo() const { return truthInfo_; }
    // "cpu-finish (...why)": how frame ms were taken (cpu-time: process CPU-ms, all threads).
    std::string timing() const {
        if (!device_.name.empty())
            return "model:" + device_.name + " (the device model's prediction for " + device_.label +
                   "; bench/devicemodel/README.md)";
        return options_.timing.name + " (" + options_.timing.reason + ")";
    }
    std::string timingName() const {
        return device_.name.empty() ? options_.timing.name : "model:" + device_.name;
    }
    // Frames rendered per session of n candidates (+ the reference): warm-up, timed rounds,
    // the accuracy frame after a cut and the irradiance-only frame.
    int rendersPerVariant() const {
        return options_.warmup + options_.rounds * options_.frames + 2;
    }

private:
    // `--timing model:NAME`: each candidate's predicted frame on the device (NaN where it could
    // not be predicted); empty for a measured timing. The candidates go to the compilers as
    // profile files (the base plus their switches) in a folder of their own.
    std::vector<double> predict(const std::vector<profile::Profile>& batch) {
        if (device_.name.empty()) return {};
        const fs::path dir = fs::temp_directory_path() /
                             ("probebench-tune-" + std::to_string(::getpid()) + "-" +
                              std::to_string(++batches_));
        fs::create_directories(dir);
        std::vector<std::string> files;
        std::vector<profile::PlatformProfile> profiles;
        bench::TunedProfileInfo info;
        info.inherit = base_.file.empty() ? base_.name : fs::absolute(base_.file).string();
        info.description = "tune candidate";
        info.width = width_;
        info.height = height_;
        info.budgetMs = base_.frameBudgetMs;
        info.budgetMiB = base_.giMemoryBudgetMiB;
        for (size_t i = 0; i < batch.size(); ++i) {
            const fs::path f = dir / ("candidate-" + std::to_string(i + 1) + ".toml");
            const std::string text = bench::tunedProfileToml(base_.switches, batch[i], info);
            writeFileAtomic(f.string(), text.data(), text.size());
            files.push_back(f.string());
            profiles.push_back(profile::loadProfile(f.string(), profileSearch()));
        }
        const shaders::ShaderStatisticsRun stats = runModelCompilers(
            {device_}, {files, reference_.name, {}, false, false, width_, height_}, a_.scene,
            probesPath_, cameraSpec(view_), 600, scene_.name,
            [](const std::string& l) { tuneProgress("  model: " + l); });
        const bench::BenchPlan plan =
            bench::makeBenchPlan(profiles, reference_, {false, width_, height_});
        const std::vector<bench::DevicePrediction> p = bench::predictDevices(
            plan, scene_, set_, view_, stats, {{device_}, false, false, {}});
        std::error_code ec;
        fs::remove_all(dir, ec);
        if (!p.at(0).error.empty()) throw Error("--timing " + a_.timing + ": " + p[0].error);
        std::vector<double> out;
        for (const bench::PredictedSession& ps : p[0].sessions)
            out.push_back(ps.variants.at(0).error.empty() ? ps.variants[0].ms : NAN);
        return out;
    }

    void start() {
        if (platform_) return;
        if (!a_.camera.empty() || !a_.view.empty()) {
            view_ = chooseView(scene_, a_.view, a_.camera);
        } else {
            const int h = std::min(height_, 180);
            const int w = std::max(16, int(double(width_) * h / height_ + 0.5));
            tuneProgress("searching the worst-case view (every pixel needs GI) at " +
                     std::to_string(w) + "x" + std::to_string(h));
            view_ = views::findWorstCaseView(scene_, set_, w, h).view;
        }
        if (a_.truth) {
            bench::BenchPlan one;
            bench::Session session;
            session.width = width_;
            session.height = height_;
            one.sessions.push_back(session);
            const std::string dir = a_.cacheDir.empty() ? bench::defaultProbeCacheDir() : a_.cacheDir;
            truth_ = bench::computeBenchTruth(scene_, view_, one, {a_.truthSpp, 32, dir, tuneProgress},
                                              &truthInfo_);
        }
        platform_ = platform::createPlatform(timingPlatform(a_.platform));
        debug_ = std::make_unique<gl::DebugOutput>();
        const gl::GlCaps caps = gl::queryCaps();
        options_.frames = a_.frames;
        options_.rounds = a_.rounds;
        options_.warmup = a_.warmup;
        // With the device model the frame time is predicted: llvmpipe only renders for the
        // accuracy, one round of one frame.
        if (!modelDeviceName(a_).empty()) {
            device_ = resolvePredictDevices(modelDeviceName(a_), {}).at(0);
            options_.frames = 1;
            options_.rounds = 1;
        }
        options_.timing = bench::chooseTiming(device_.name.empty() ? a_.timing : "cpu", caps,
                                              gl::detectDriverQuirks());
        options_.es = caps.es;
        options_.fetchFloor = false;
        options_.pixelsPerDegree = a_.ppd;
        options_.progress = [](const std::string& line) { tuneProgress("  " + line); };
        context_ = bench::benchContext(*platform_, caps);
        tuneProgress("timing " + options_.timing.name + " on " + caps.renderer + ", " +
                 std::to_string(width_) + "x" + std::to_string(height_) + ", " +
                 std::to_string(a_.rounds) + " round(s) x " + std::to_string(a_.frames) +
                 " frame(s) per candidate");
    }

    const TuneArgs& a_;
    const scene::Scene& scene_;
    const probes::ProbeSet& set_;
    const profile::PlatformProfile &base_, &reference_;
    int width_, height_;
    scene::View view_;
    std::unique_ptr<platform::Platform> platform_;
    std::unique_ptr<gl::DebugOutput> debug_;
    bench::RunnerOptions options_;
    nlohmann::json context_;
    bench::TruthBySize truth_; // --truth: the truth of view_ at width_ x height_
    nlohmann::json truthInfo_;
    devicemodel::DeviceSpec device_; // --timing model:NAME; name "" otherwise
    int batches_ = 0;

public:
    std::string probesPath_; // the probe file the compilers' workers read (--timing model:)
};

probes::ProbeSet tuneProbes(const TuneArgs& a, const scene::Scene& s, std::string& path) {
    if (!a.probes.empty()) {
        path = a.probes;
        return readProbesForScene(a.probes, s, a.force);
    }
    probes::ProbeSet set = bench::benchProbes(
        s, a.volumes, a.cacheDir.empty() ? bench::defaultProbeCacheDir() : a.cacheDir, &path,
        tuneProgress);
    probes::attachVolumeRanks(set, path);
    return set;
}

void printComparison(const bench::TuneCandidate& found, const bench::TuneMeasurement& again,
                     double memoryAgain, const std::string& file) {
    const double ratio = again.frameMs / found.m.frameMs;
    std::printf("\nre-measured %s as loaded from the file:\n", file.c_str());
    std::printf("  %-10s %12s %12s\n", "", "search", "re-measured");
    std::printf("  %-10s %12.2f %12.2f  (%+.1f%%)\n", "frame ms", found.m.frameMs, again.frameMs,
                100.0 * (ratio - 1.0));
    std::printf("  %-10s %12.3f %12.3f\n", "GI MiB", found.memoryMiB, memoryAgain);
    std::printf("  %-10s %12.4f %12.4f\n", "FLIP", found.m.flip, again.flip);
    // Accuracy and memory are deterministic; time is within noise when it moved less than
    // llvmpipe's run-to-run spread (DESIGN.md: about +-20% between runs).
    const bool same = again.flip == found.m.flip && memoryAgain == found.memoryMiB;
    std::printf("  %s\n", same && std::abs(ratio - 1.0) <= 0.2
                              ? "reproduces: FLIP and memory identical, time within +-20%"
                          : same ? "FLIP and memory identical; time moved more than +-20% "
                                   "(noisy machine? see the load average)"
                                 : "warning: FLIP or memory differ from the search's");
}

int runTune(const TuneArgs& a) {
    validateTune(a);
    prepareOutputParent("--out", a.out, a.mkdir); // the one rule (OutputPaths.h)
    const profile::ProfileSearch search = profileSearch();
    profile::PlatformProfile base = profile::loadProfile(a.base, search);
    for (const std::string& kv : a.sets)
        base.switches.applyOverride(kv);
    const profile::PlatformProfile reference = profile::loadProfile(a.reference, search);
    const int width = a.width > 0 ? a.width : base.width;
    const int height = a.height > 0 ? a.height : base.height;
    const scene::Scene s = loadSceneWithOverrides(a.scene);
    std::string probesPath;
    const probes::ProbeSet set = tuneProbes(a, s, probesPath);
    const int dynamicObjects = int(render::findDynamicObjects(s).objects.size());

    bench::TuneContext context;
    context.dynamicObjects = dynamicObjects;
    context.volumeLodValues = bench::volumeLodLevels(set);
    const bench::TuneSpace space = bench::makeTuneSpace(base.switches, context, a.search);
    const bench::MemoryFn memory = [&](const profile::Profile& p) {
        try {
            return render::estimateGiMemory(p, set, width, height, dynamicObjects).totalMiB();
        } catch (const Error&) {
            return std::numeric_limits<double>::infinity(); // gi.volume_lod cannot apply
        }
    };
    Measurer measurer(a, s, set, base, reference, width, height);
    measurer.probesPath_ = probesPath;
    const bench::MeasureFn measure = [&](const std::vector<profile::Profile>& batch) {
        return measurer(batch);
    };
    bench::TuneOptions o;
    o.budgetMs = a.budgetMs;
    o.budgetMiB = a.budgetMiB;
    o.maxExhaustive = a.maxExhaustive;
    o.maxPasses = a.maxPasses;
    o.progress = tuneProgress;
    if (!modelDeviceName(a).empty()) o.timeSource = "model: " + modelDeviceName(a);
    const bench::TuneResult r = bench::runTune(space, memory, measure, o);
    if (r.chosen < 0) throw Error("tune: " + bench::nothingFitsMessage(r, o));
    const bench::TuneCandidate& best = r.candidates[size_t(r.chosen)];

    // Write the profile, load it back and re-measure it in a session of its own.
    std::error_code ec;
    if (fs::path parent = fs::path(a.out).parent_path(); !parent.empty())
        fs::create_directories(parent, ec);
    bench::TunedProfileInfo info;
    info.inherit = inheritRef(a, base);
    char desc[200];
    std::snprintf(desc, sizeof desc, "tuned from %s for %g ms and %g MiB GI at %dx%d",
                  base.name.c_str(), a.budgetMs, a.budgetMiB, width, height);
    info.description = desc;
    info.width = width;
    info.height = height;
    info.budgetMs = a.budgetMs;
    info.budgetMiB = a.budgetMiB;
    char measured[600];
    std::snprintf(measured, sizeof measured,
                  "measured: %.2f ms per frame (median, timing %s), GI memory %.3f MiB (probes + "
                  "GI targets), FLIP %.4f vs %s",
                  best.m.frameMs, measurer.timingName().c_str(), best.memoryMiB, best.m.flip,
                  a.truth ? ("the path-traced truth (" + std::to_string(a.truthSpp) + " spp)").c_str()
                          : ("profile '" + reference.name + "'").c_str());
    info.comments = {
        "Written by `probebench tune`: the most accurate configuration found that fits the "
        "budgets below on the device named here.",
        "device: " +
            (modelDeviceName(a).empty()
                 ? measurer.context().value("gl_renderer", std::string("?"))
                 : "model:" + modelDeviceName(a) + " (predicted frame; accuracy rendered on " +
                       measurer.context().value("gl_renderer", std::string("?")) + ")") +
            "; load average " +
            bench::loadAverage(),
        "scene " + s.name + ", probes " + probesPath + ", search: " + r.method + ", " +
            std::to_string(r.variantsMeasured) + " candidate measurement(s) in " +
            std::to_string(r.sessions) + " session(s)",
        measured,
        std::string("[budget] gi_memory_mib: ") + profile::kGiMemoryDefinition + "."};
    const std::string text = bench::tunedProfileToml(base.switches, best.switches, info);
    // Staged beside --out, re-measured from that file, renamed to --out only when it holds its
    // budget (or --accept-over-budget): a failed tune leaves no profile behind.
    const fs::path staged = fs::path(a.out).parent_path() /
                            ("." + fs::path(a.out).stem().string() + ".partial.toml");
    struct RemoveUnlessKept {
        fs::path path;
        bool keep = false;
        ~RemoveUnlessKept() {
            std::error_code ec;
            if (!keep) fs::remove(path, ec);
        }
    } stagedFile{staged};
    writeFileAtomic(staged.string(), text.data(), text.size());
    const profile::PlatformProfile loaded = profile::loadProfileFile(staged.string(), search);
    if (!(loaded.switches == best.switches) || loaded.width != width || loaded.height != height)
        throw Error(a.out + ": the written profile does not load back to the tuned switches");

    std::cout << "searched " << r.distinct << " distinct configuration(s) of " << space.axes.size()
              << " switch(es) by " << r.method << "; " << r.overMemory
              << " over the memory budget (not rendered); " << r.variantsMeasured
              << " candidate measurement(s) in " << r.sessions << " session(s), "
              << measurer.rendersPerVariant() << " frames each (+ the reference per session): "
              << (r.variantsMeasured + r.sessions) * measurer.rendersPerVariant()
              << " frames rendered\n";
    for (const std::string& f : space.fixed)
        std::cout << "  held at the base: " << f << "\n";
    std::cout << "frame ms: timing " << measurer.timing() << "\n";
    std::cout << bench::paretoTable(r, o);
    std::printf("chosen: %s: %.2f ms (budget %g), %.3f MiB (budget %g), FLIP %.4f\n",
                best.label.c_str(), best.m.frameMs, a.budgetMs, best.memoryMiB, a.budgetMiB,
                best.m.flip);
    tuneProgress("re-measuring " + a.out);
    const bench::TuneMeasurement again = measurer({loaded.switches}).front();
    if (!again.ok) throw Error(a.out + ": the written profile did not run: " + again.error);
    printComparison(best, again, memory(loaded.switches), a.out);
    if (const std::string over = bench::overBudgetProblem(again.frameMs, best.m.frameMs, a.budgetMs);
        !over.empty()) {
        if (!a.acceptOverBudget)
            throw Error("tune: " + a.out + ": " + over +
                        "; nothing written (--accept-over-budget writes it anyway; more "
                        "--rounds steady the measure)");
        std::printf("  note: %s; written anyway (--accept-over-budget)\n", over.c_str());
    }
    fs::rename(staged, a.out);
    stagedFile.keep = true;
    std::printf("wrote %s\n", a.out.c_str());
    if (a.json) {
        nlohmann::json j = bench::tuneJson(r, o);
        j["context"] = measurer.context();
        j["scene"] = s.name;
        j["probes_file"] = probesPath;
        j["width"] = width;
        j["height"] = height;
        j["base"] = base.name;
        j["reference"] = reference.name;
        j["accuracy_target"] = a.truth ? "truth" : "reference"; // what "flip" is measured against
        j["truth"] = a.truth ? measurer.truthInfo() : nlohmann::json(nullptr);
        j["out"] = a.out;
        j["renders_per_candidate"] = measurer.rendersPerVariant();
        j["timing"] = measurer.timing();
        j["frames_rendered"] = (r.variantsMeasured + r.sessions) * measurer.rendersPerVariant();
        j["remeasure"] = {{"frame_ms", again.frameMs},
                          {"flip", again.flip},
                          {"gi_memory_mib", memory(loaded.switches)}};
        writeJson(a.json, j.dump(2) + "\n");
        if (!a.json.toStdout()) std::printf("wrote %s\n", a.json.file().c_str());
    }
    return 0;
}

const RegisterCommand registerTune{
    {"tune",
     "Search the switches for the most accurate configuration within a frame-time and a GI "
     "memory budget on this device; write it as a profile",
     52, [](CLI::App& cmd) {
         auto a = std::make_shared<TuneArgs>();
         addSceneOptions(cmd, a->scene);
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--budget-ms", a->budgetMs,
                        "Frame-time budget: median frame ms on THIS device at the output size")
             ->required();
         cmd.add_flag("--accept-over-budget", a->acceptOverBudget,
                      "Write the profile even when its re-measure (loaded back from the file) "
                      "is over --budget-ms (else: an error, exit 1, nothing written)");
         cmd.add_option("--budget-mib", a->budgetMiB,
                        std::string("GI memory budget, MiB (") + profile::kGiMemoryDefinition +
                            "; bench's GI MiB counts the same)")
             ->required();
         cmd.add_option("--out", a->out, "Profile to write (.toml; inherits --base)")->required();
         cmd.add_option("--base", a->base,
                        "Profile the search starts from and the written profile inherits (name "
                        "or .toml); its output size unless --width/--height")
             ->capture_default_str();
         cmd.add_option("--reference", a->reference, "Accuracy baseline profile (FLIP vs it)")
             ->capture_default_str();
         cmd.add_option("--set", a->sets, "Switch key=value applied to the base (repeatable)");
         cmd.add_flag("--truth", a->truth,
                      "Minimise FLIP against the path-traced ground truth of the view "
                      "(probebench truth; cached) instead of against --reference");
         cmd.add_option("--truth-spp", a->truthSpp, "Samples per pixel of that truth")
             ->capture_default_str();
         cmd.add_option("--search", a->search,
                        "Only these switches are searched, comma-separated (default: every "
                        "switch of the table except the guards gi.guard_*, which are held at "
                        "the base unless named here)")
             ->delimiter(',');
         cmd.add_option("--width", a->width, "Output width (default: the base profile's)");
         cmd.add_option("--height", a->height, "Output height (default: the base profile's)");
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--probes", a->probes,
                        "Probe file (probebench bake; its FILE.ranks.json adds rank_budget_mib "
                        "levels); default: bake --volumes once and cache it");
         cmd.add_option("--volumes", a->volumes,
                        "Without --probes: the volumes to bake (auto, stored sparse as bake does; "
                        "auto-uniform or a file)")
             ->capture_default_str();
         cmd.add_option("--cache-dir", a->cacheDir, "Folder of the baked-probe cache");
         cmd.add_option("--view", a->view, "A named view instead of the worst case");
         cmd.add_option("--camera", a->camera, "Camera px,py,pz,tx,ty,tz[,fovdeg] instead");
         cmd.add_option("--frames", a->frames,
                        "Timed frames per candidate per round, as `bench --frames` (not "
                        "`render --frames`, the frames to show or play)")
             ->capture_default_str();
         cmd.add_option("--rounds", a->rounds, "Interleaved rounds per session")
             ->capture_default_str();
         cmd.add_option("--warmup", a->warmup, "Untimed frames per candidate first")
             ->capture_default_str();
         cmd.add_option("--timing", a->timing,
                        "auto, cpu, cpu-time or query (as bench), or model:NAME: the device "
                        "model's predicted frame on device NAME (probebench devices) instead of "
                        "this machine's; needs scripts/mesa-shim.sh")
             ->capture_default_str();
         cmd.add_option("--max-exhaustive", a->maxExhaustive,
                        "Measure every candidate when at most this many fit the memory budget; "
                        "else coordinate descent")
             ->capture_default_str();
         cmd.add_option("--max-passes", a->maxPasses, "Coordinate-descent passes at most")
             ->capture_default_str();
         cmd.add_option("--ppd", a->ppd, "FLIP viewing condition, pixels per degree")
             ->capture_default_str();
         cmd.add_flag("--mkdir", a->mkdir, "Create the missing parent folder of --out and --json (else a missing folder is an error, before any work)");
         a->json.add(cmd, "The whole search");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runTune(*a);
         };
     }}};

} // namespace
} // namespace pb::app
