#pragma once
// What the regression gate compares (bench/gate/README.md): the suite it runs and, per
// profile, what one run measured - exact counters, accuracy against the reference, and the
// profile/reference frame-time ratios of its interleaved rounds - plus callgrind instruction
// counts keyed by the toolchain that produced them, and the weak GPUs' shader compilers'
// statistics keyed by the Mesa that built them. A baseline file (bench/baselines/*.json) is one
// such record written on purpose (`probebench gate --update`). GL-free.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pb::gate {

inline constexpr const char* kGateSchema = "probebench.gate/1";

struct TimingSettings {
    std::string method = "cpu-time"; // the bench's SectionTimer method (bench --timing)
    int frames = 3;                  // K: frames per round; the round's value is their median
    int warmup = 2;                  // frames per renderer before any round (never counted)
    int minRounds = 9;
    int maxRounds = 30;           // budget while the verdict is unknown
    int quickMaxRounds = 15;      // the same with --quick
    int roundStep = 6;            // rounds added per step while unknown
    // Past the round budget, a verdict still unknown gets more steps until the timing has run
    // this long (seconds; quick: with --quick): a noisy runner is given time to decide.
    double timeBudgetSeconds = 90, quickTimeBudgetSeconds = 30;
    double alpha = 0.01;          // p for "different"
    double threshold = 0.03;      // --against: relative frame-time shift that matters
    double ratioThreshold = 0.10; // profile/reference ratio against the baseline's ratios
};

struct AccuracyTolerance {
    double flipAbs = 2e-4, flipRel = 0.10;     // FLIP mean may rise by max(abs, rel x baseline)
    double psnrDb = 0.5;                       // PSNR may fall by this
    double relMseAbs = 1e-7, relMseRel = 0.25; // relative MSE of the GI may rise by abs + rel x
};

// The Embree ISA the gate traces every ray with (its bake and the cost model's primary rays):
// SSE2, the x86-64 baseline. A bake still differs between CPU vendors in the last bits (the
// approximate reciprocals Embree's kernels refine differ between Intel and AMD), and can
// classify a probe differently; so the counters never come from this machine's bake but from
// the probe file committed beside the baseline (bench/baselines/README.md "Across machines").
inline constexpr const char* kGateEmbreeIsa = "sse2";

struct GateSuite {
    std::string scene = "rooms";
    std::string volumes = "bench/baselines/rooms_gate.toml"; // relative: to the repository
    std::string camera; // px,py,pz,tx,ty,tz,fov (fixed, so every run renders the same frame)
    int width = 384, height = 216;
    std::vector<std::string> profiles; // every one measured; the reference among them
    std::string reference = "reference";
    TimingSettings timing;
    AccuracyTolerance tolerance;
    double callgrindTolerance = 0.005; // relative, of the frame's instructions
    // `probebench shaders` targets whose compiler statistics are gated (bench/gate/README.md
    // "Shader statistics"): one Adreno, one Bifrost and one Valhall Mali by default, the
    // handheld-class parts the profiles aim at. A baseline without the key gets these.
    std::vector<std::string> shaderTargets = {"adreno-630", "mali-g52", "mali-g57"};
};

// What a run's figures depend on besides the code and the suite (compared, unlike
// `recorded`): where it differs from the baseline's, the gate says so in a note and compares
// the figures that depend on it within tolerances (bench/baselines/README.md).
struct GateEnvironment {
    std::string embreeIsa;  // "" in a baseline written before it was recorded
    std::string glRenderer; // GL_RENDERER: llvmpipe names its LLVM and SIMD width
    std::string cpu;        // /proc/cpuinfo's model name: whose bake `bake` is
};

struct AccuracyValues {
    bool measured = false;
    double flipMean = 0, psnr = 0, relMseGi = 0; // psnr +inf: identical
};

using Counters = std::vector<std::pair<std::string, std::int64_t>>;

struct ProfileRecord {
    std::string name;
    Counters counters; // exact
    // Informational (not compared): the GL pass's evaluated pixels per volume, for the
    // model-vs-GL agreement check.
    Counters glPixels;
    // Informational (not compared): the apply shader's invocations per volume (the pass's
    // atomic counter, GiInvocationCounter); empty where the context cannot count. Where they
    // exceed glPixels the device shaded work that evaluated nothing (gate row gl-invocations).
    Counters glInvocations;
    AccuracyValues accuracy;          // against the suite's reference (not for the reference)
    std::vector<double> ratioSamples; // per round: profile frame / reference frame
    const std::int64_t* counter(const std::string& key) const;
};

// The toolchain an instruction count depends on; a baseline with another key is skipped.
struct CallgrindKey {
    std::string mesa, llvm, compiler, valgrind;
    bool operator==(const CallgrindKey& o) const;
    std::string text() const; // "Mesa 22.3.6, LLVM 15.0.6, GCC 12.2.0, valgrind-3.19.0"
};

struct CallgrindRecord {
    CallgrindKey key;
    // Per profile: instructions per frame section (exclusive) and "frame" (their sum).
    std::vector<std::pair<std::string, Counters>> profiles;
    const Counters* profile(const std::string& name) const;
};

// What a shader compiler's statistics depend on: the Mesa that built the compilers and the
// drivers built into it (scripts/mesa-shim.sh); a baseline with another key is skipped.
struct ShaderKey {
    std::string mesa;                 // "22.3.6-1+deb12u2": the install's Debian version
    std::vector<std::string> drivers; // as built: "freedreno", "panfrost", ...
    bool operator==(const ShaderKey& o) const;
    std::string text() const; // "Mesa 22.3.6-1+deb12u2 (freedreno, panfrost, v3d, nouveau)"
};

// One pass of one profile on one target: its heaviest fragment program's figures as exact
// integers (ShaderCounters.h names them).
struct ShaderPassRecord {
    std::string profile, pass;
    Counters counters;
};

struct ShaderTargetRecord {
    std::string target; // "mali-g52"
    std::vector<ShaderPassRecord> passes;
    const ShaderPassRecord* pass(const std::string& profile, const std::string& pass) const;
};

struct ShaderRecord {
    ShaderKey key;
    std::vector<ShaderTargetRecord> targets;
    const ShaderTargetRecord* target(const std::string& name) const;
};

struct GateRecord {
    GateSuite suite;
    nlohmann::json recorded = nlohmann::json::object(); // where and when (never compared)
    GateEnvironment environment;
    // Identity ("<count> probes, <volumes>, <format>, fnv1a <hex>") of the probe data every
    // counter, accuracy and timing figure is measured with: the probe file committed beside the
    // baseline (committedProbesPath), which --update writes from the recording machine's bake.
    std::string probes;
    // Identity of this machine's own bake of the suite: compared apart, so a change to the
    // bake is still seen, and a bake that differs only because the CPU does is a note.
    std::string bake;
    std::vector<ProfileRecord> profiles;
    std::vector<CallgrindRecord> callgrind; // at most one per key
    std::vector<ShaderRecord> shaders;      // at most one per key
    const ProfileRecord* profile(const std::string& name) const;
    const CallgrindRecord* callgrindFor(const CallgrindKey& key) const;
    const ShaderRecord* shadersFor(const ShaderKey& key) const;
};

// The probe file committed beside a baseline: "<baseline without .json>.probes.gz".
std::string committedProbesPath(const std::string& baselinePath);

nlohmann::json recordJson(const GateRecord& r);
// Throws pb::Error "<source>: <key>: <problem>" for a wrong schema, a missing or mistyped key.
GateRecord recordFromJson(const nlohmann::json& j, const std::string& source);
// Throws pb::Error "<path>: <problem>" (missing file, not JSON, wrong content).
GateRecord readGateRecord(const std::string& path);
// Atomic (temporary file + rename); 2-space JSON with a final newline, keys sorted, so a
// baseline's diff shows exactly what changed.
void writeGateRecord(const std::string& path, const GateRecord& r);

} // namespace pb::gate
