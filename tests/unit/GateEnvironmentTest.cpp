// What the gate does when the machine differs from the baseline's (bench/baselines/README.md
// "Across machines"): the environment round-trips through the baseline JSON, an older file
// without it still reads; a bake on another Embree ISA lets only the bake-dependent counters
// move, within the suite's tolerance and with a note, while every other counter stays exact;
// on the same ISA nothing is relaxed. And PB_EMBREE_ISA: a name Embree would silently replace
// by SSE2 is an error, and the gate's pin is what the process then traces with.
#include "bench/gate/GateOutcome.h"
#include "bench/gate/GateRecord.h"
#include "core/Error.h"
#include "probes/bake/EmbreeIsa.h"
#include "probes/bake/RayScene.h"
#include "scene/BuiltinScenes.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace pb::gate;

namespace {

GateRecord record(const std::string& isa) {
    GateRecord r;
    r.suite.camera = "1,2,3,0,0,0,60";
    r.suite.profiles = {"reference"};
    r.environment = {isa, "llvmpipe (LLVM 15.0.6, 256 bits)"};
    r.probes = "10 probes, 1 volumes, rgba16f, fnv1a 0123";
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

// What a bake on another ISA did to the gate's suite: a few probes classified differently,
// so fetches, bytes and cache lines move by a few hundredths of a percent.
GateRecord bakedElsewhere(const std::string& isa) {
    GateRecord now = record(isa);
    now.probes = "10 probes, 1 volumes, rgba16f, fnv1a 4567";
    add(now, "model.fetches.irradiance", -30);
    add(now, "model.fetches.visibility", -30);
    add(now, "model.probe_bytes_read", -1920);
    add(now, "cache.xyz/fused.lines", -15);
    add(now, "cache.xyz/fused.hits", -14);
    return now;
}

} // namespace

TEST(GateEnvironment, RoundTripsAndAnOlderBaselineStillReads) {
    const GateRecord r = record("sse2");
    const GateRecord back = recordFromJson(recordJson(r), "mem");
    EXPECT_EQ(back.environment.embreeIsa, "sse2");
    EXPECT_EQ(back.environment.glRenderer, "llvmpipe (LLVM 15.0.6, 256 bits)");
    nlohmann::json old = recordJson(r);
    old.erase("environment");
    old["suite"].erase("isa_counter_tolerance");
    const GateRecord fromOld = recordFromJson(old, "old.json");
    EXPECT_EQ(fromOld.environment.embreeIsa, "");
    EXPECT_EQ(fromOld.suite.isaCounterTolerance, GateSuite().isaCounterTolerance);
}

TEST(GateEnvironment, AnotherIsasBakeMovesOnlyBakeCountersWithinTheTolerance) {
    const GateOutcome o = compare(record("sse2"), bakedElsewhere("avx512"));
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_EQ(row(o, "probe data")->status, RowStatus::Skipped);
    EXPECT_TRUE(hasNote(o, "baked with Embree avx512, the baseline's with sse2"));
    EXPECT_NE(row(o, "model.fetches")->note.find("within"), std::string::npos);
    EXPECT_NE(gateTable(o).find("avx512"), std::string::npos) << "the note is printed";

    // Past the tolerance, or any counter that does not follow from the bake: CHANGED.
    GateRecord far = bakedElsewhere("avx512");
    add(far, "model.fetches.irradiance", -1000); // 1% of the baseline's
    EXPECT_EQ(compare(record("sse2"), far).exitCode(), kExitRegression);
    for (const char* key : {"gl.gi-apply.draws", "model.gi_pixels", "cache.preset.line_bytes"}) {
        GateRecord other = bakedElsewhere("avx512");
        add(other, key, 1);
        const GateOutcome f = compare(record("sse2"), other);
        EXPECT_EQ(f.exitCode(), kExitRegression) << key;
        EXPECT_EQ(f.deterministicFailures(), 1) << key;
    }
}

TEST(GateEnvironment, TheSameIsaOrAnUnrecordedOneStaysExact) {
    for (const std::string baseIsa : {"sse2", ""}) {
        const GateOutcome o = compare(record(baseIsa), bakedElsewhere("sse2"));
        EXPECT_EQ(o.exitCode(), kExitRegression) << baseIsa;
        EXPECT_EQ(row(o, "probe data")->status, RowStatus::Changed) << baseIsa;
        EXPECT_EQ(row(o, "model.fetches")->status, RowStatus::Changed) << baseIsa;
        EXPECT_EQ(hasNote(o, "does not record the Embree ISA"), baseIsa.empty());
    }
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
    EXPECT_THROW(pb::probes::RayScene{s}, pb::Error);
    EXPECT_THROW(pb::probes::embreeIsa(), pb::Error);
    ::setenv("PB_EMBREE_ISA", "sse2", 1);
    EXPECT_EQ(pb::probes::embreeIsa(), "sse2");
    EXPECT_EQ(pb::probes::embreeDeviceConfig(), "isa=sse2");
    ::unsetenv("PB_EMBREE_ISA");
    EXPECT_THROW(pb::probes::pinEmbreeIsa("avx3"), pb::Error);
    pb::probes::pinEmbreeIsa("sse2");
    EXPECT_EQ(pb::probes::embreeIsa(), "sse2");
    const pb::probes::RayScene rays(s); // traced with it
    EXPECT_TRUE(rays.intersect({0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}).hit());
    pb::probes::pinEmbreeIsa(""); // Embree chooses again, for the tests after this one
}
#endif
