// What the gate does when the machine differs from the baseline's (bench/baselines/README.md
// "Across machines"): the environment and the bake's identity round-trip through the baseline
// JSON, an older file without them still reads; a bake that differs on another CPU or Embree
// ISA is a note while every counter stays exact (they are measured with the committed probe
// file) but the cache replay's lines and hits, which pass within 0.05% there; a bake that
// differs on the recording CPU fails. And PB_EMBREE_ISA: a name Embree would silently replace
// by SSE2 is an error, and the gate's pin is what the process then traces with.
#include "bench/gate/GateOutcome.h"
#include "bench/gate/GateRecord.h"
#include "core/Error.h"
#include "raytrace/EmbreeIsa.h"
#include "raytrace/RayScene.h"
#include "scene/BuiltinScenes.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace pb::gate;

namespace {

GateRecord record(const std::string& isa) {
    GateRecord r;
    r.suite.camera = "1,2,3,0,0,0,60";
    r.suite.profiles = {"reference"};
    r.environment = {isa, "llvmpipe (LLVM 15.0.6, 256 bits)", "Intel(R) Xeon(R) CPU"};
    r.probes = "10 probes, 1 volumes, rgba16f, fnv1a 0123";
    r.bake = r.probes;
    ProfileRecord p;
    p.name = "reference";
    p.counters = {{"gl.gi-apply.draws", 3},
                  {"model.gi_pixels", 1000},
                  {"model.fetches.irradiance", 100000},
                  {"model.fetches.visibility", 100000},
                  {"model.probe_bytes_read", 6400000},
                  {"cache.preset.line_bytes", 64},
                  {"cache.xyz/fused.lines", 50000},
                  {"cache.xyz/fused.hits", 49000}};
    r.profiles = {p};
    return r;
}

void add(GateRecord& r, const std::string& key, std::int64_t delta) {
    for (auto& [k, v] : r.profiles[0].counters)
        if (k == key) v += delta;
}

GateOutcome compare(const GateRecord& base, const GateRecord& now) {
    GateOutcome o;
    compareRecords(base, now, o);
    return o;
}

const GateRow* row(const GateOutcome& o, const std::string& name) {
    for (const GateRow& r : o.rows)
        if (r.name.rfind(name, 0) == 0) return &r;
    return nullptr;
}

bool hasNote(const GateOutcome& o, const std::string& part) {
    for (const std::string& n : o.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

GateRecord bakedElsewhere(const std::string& isa, const std::string& cpu) {
    GateRecord now = record(isa);
    now.environment.cpu = cpu;
    now.bake = "10 probes, 1 volumes, rgba16f, fnv1a 4567";
    return now;
}

} // namespace

TEST(GateEnvironment, RoundTripsAndAnOlderBaselineStillReads) {
    const GateRecord r = record("sse2");
    const GateRecord back = recordFromJson(recordJson(r), "mem");
    EXPECT_EQ(back.environment.embreeIsa, "sse2");
    EXPECT_EQ(back.environment.glRenderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_EQ(back.environment.cpu, "Intel(R) Xeon(R) CPU");
    EXPECT_EQ(back.bake, r.bake);
    nlohmann::json old = recordJson(r);
    old.erase("environment");
    old.erase("bake");
    old["suite"]["isa_counter_tolerance"] = 0.005; // written by older versions: ignored
    const GateRecord fromOld = recordFromJson(old, "old.json");
    EXPECT_EQ(fromOld.environment.embreeIsa, "");
    EXPECT_EQ(fromOld.bake, "");
    EXPECT_EQ(committedProbesPath("bench/baselines/rooms.json"),
              "bench/baselines/rooms.probes.gz");
}

// The AMD-vs-Intel case: this machine's bake differs in the last bits, but every counter was
// measured with the committed probe file, so they are equal and the bake row is a note.
TEST(GateEnvironment, AnotherCpusBakeIsANoteAndEveryOtherCounterStaysExact) {
    const GateOutcome o = compare(record("sse2"), bakedElsewhere("sse2", "AMD EPYC"));
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_EQ(row(o, "probe data")->status, RowStatus::Ok);
    EXPECT_EQ(row(o, "bake on this machine")->status, RowStatus::Skipped);
    EXPECT_TRUE(hasNote(o, "CPU 'AMD EPYC', the baseline's 'Intel(R) Xeon(R) CPU'"));
    EXPECT_NE(gateTable(o).find("AMD EPYC"), std::string::npos) << "the note is printed";
    // Another CPU relaxes nothing but the cache replay (next test): any other counter that
    // moves still fails, by exactly one row.
    for (const char* key : {"gl.gi-apply.draws", "model.fetches.irradiance",
                            "model.probe_bytes_read", "model.gi_pixels"}) {
        GateRecord other = bakedElsewhere("sse2", "AMD EPYC");
        add(other, key, 1);
        const GateOutcome f = compare(record("sse2"), other);
        EXPECT_EQ(f.exitCode(), kExitRegression) << key;
        EXPECT_EQ(f.deterministicFailures(), 1) << key;
    }
    // So does probe data that is not the baseline's own (a baseline and a probe file written
    // apart).
    GateRecord stale = bakedElsewhere("sse2", "AMD EPYC");
    stale.probes = "10 probes, 1 volumes, rgba16f, fnv1a 89ab";
    EXPECT_EQ(row(compare(record("sse2"), stale), "probe data")->status, RowStatus::Changed);
}

// The cache replay's lines and hits follow the last bits of CPU arithmetic (an AMD EPYC counts
// one line more than the recording Intel Xeon): on another machine they pass within
// kOtherMachineCacheTolerance, with a note; beyond it, or on the recording CPU, they fail.
TEST(GateEnvironment, CacheLinesPassWithinTheirToleranceOnlyOnAnotherMachine) {
    const auto outcome = [](const std::string& cpu, std::int64_t lines, std::int64_t hits) {
        GateRecord now = bakedElsewhere("sse2", cpu);
        add(now, "cache.xyz/fused.lines", lines);
        add(now, "cache.xyz/fused.hits", hits);
        return compare(record("sse2"), now);
    };
    const GateOutcome amd = outcome("AMD EPYC", 1, 1);
    EXPECT_EQ(amd.exitCode(), 0);
    EXPECT_EQ(row(amd, "cache.xyz/fused")->status, RowStatus::Ok);
    EXPECT_NE(row(amd, "cache.xyz/fused")->note.find("another machine"), std::string::npos);
    EXPECT_TRUE(hasNote(amd, "cache.* lines and hits pass within"));
    // 25 of 50000 lines is the tolerance's edge (5e-4); 26 is past it; 500 is a shader change.
    EXPECT_EQ(outcome("AMD EPYC", 25, 0).exitCode(), 0);
    EXPECT_EQ(outcome("AMD EPYC", 26, 0).exitCode(), kExitRegression);
    EXPECT_EQ(outcome("AMD EPYC", 0, -500).exitCode(), kExitRegression);
    // Another Embree ISA on the recording CPU is another machine too; the same CPU and ISA is
    // not: there one line fails.
    GateRecord isa = bakedElsewhere("avx2", "Intel(R) Xeon(R) CPU");
    add(isa, "cache.xyz/fused.lines", 1);
    EXPECT_EQ(compare(record("sse2"), isa).exitCode(), 0);
    const GateOutcome same = outcome("Intel(R) Xeon(R) CPU", 1, 1);
    EXPECT_EQ(row(same, "cache.xyz/fused")->status, RowStatus::Changed);
    EXPECT_FALSE(hasNote(same, "cache.* lines and hits pass within"));
}

TEST(GateEnvironment, AChangedBakeOnTheRecordingCpuFails) {
    const GateOutcome same = compare(record("sse2"), bakedElsewhere("sse2", "Intel(R) Xeon(R) CPU"));
    EXPECT_EQ(same.exitCode(), kExitRegression);
    EXPECT_EQ(row(same, "bake on this machine")->status, RowStatus::Changed);
    // Another Embree ISA on the same CPU (PB_EMBREE_ISA) is a machine difference, noted.
    const GateOutcome isa = compare(record("sse2"), bakedElsewhere("avx2", "Intel(R) Xeon(R) CPU"));
    EXPECT_EQ(isa.exitCode(), 0);
    EXPECT_TRUE(hasNote(isa, "Embree avx2, the baseline's sse2"));
    // The same bake everywhere: ok.
    GateRecord equal = record("sse2");
    EXPECT_EQ(row(compare(record("sse2"), equal), "bake on this machine")->status, RowStatus::Ok);
}

TEST(GateEnvironment, AnotherGlRendererIsNotedNotRelaxed) {
    GateRecord now = record("sse2");
    now.environment.glRenderer = "llvmpipe (LLVM 15.0.6, 128 bits)";
    const GateOutcome o = compare(record("sse2"), now);
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_TRUE(hasNote(o, "128 bits"));
    add(now, "gl.gi-apply.draws", 1);
    EXPECT_EQ(compare(record("sse2"), now).exitCode(), kExitRegression);
}

#if defined(__x86_64__)
TEST(EmbreeIsa, AnUnknownNameIsAnErrorAndThePinIsUsed) {
    const pb::scene::Scene s = pb::scene::makeCornellScene();
    ::setenv("PB_EMBREE_ISA", "avx512skx", 1); // Embree would quietly run SSE2 for this
    EXPECT_THROW(pb::raytrace::RayScene{s}, pb::Error);
    EXPECT_THROW(pb::raytrace::embreeIsa(), pb::Error);
    ::setenv("PB_EMBREE_ISA", "sse2", 1);
    EXPECT_EQ(pb::raytrace::embreeIsa(), "sse2");
    EXPECT_EQ(pb::raytrace::embreeDeviceConfig(), "isa=sse2");
    ::unsetenv("PB_EMBREE_ISA");
    EXPECT_THROW(pb::raytrace::pinEmbreeIsa("avx3"), pb::Error);
    pb::raytrace::pinEmbreeIsa("sse2");
    EXPECT_EQ(pb::raytrace::embreeIsa(), "sse2");
    const pb::raytrace::RayScene rays(s); // traced with it
    EXPECT_TRUE(rays.intersect({0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}).hit());
    pb::raytrace::pinEmbreeIsa(""); // Embree chooses again, for the tests after this one
}
#endif
