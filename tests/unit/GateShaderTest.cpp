// The gate's shader statistics (bench/gate/README.md "Shader statistics"): a compiler's
// figures become exact integer counters (cycles in milli-cycles), a run becomes a record per
// target, suite profile and pass, the record round-trips through the baseline JSON (an older
// baseline without it still reads, with the default targets); against the same Mesa every
// counter is exact - a change, an appearing or vanishing pass fails with exit 3, naming target,
// profile, pass, figure, old and new -, another Mesa's record or none is a note, a failed
// target is a failure, and compilers that are not built are a note except on CI against a
// baseline that has shader statistics.
#include "bench/gate/GateOutcome.h"
#include "bench/gate/GateRecord.h"
#include "bench/gate/PredictionCounters.h"
#include "bench/gate/ShaderComparison.h"
#include "bench/gate/ShaderCounters.h"
#include "bench/shaders/DriverStatistics.h"
#include "core/Error.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace pb::gate;

namespace {

const char* kGateShaderBifrostLine =
    "MESA_SHADER_FRAGMENT shader: 132 inst, 4.041667 cycles, 3.8 arith, 4.041667 texture, "
    "0.5 vary, 0.0 ldst, 2 threads, 1 loops, 0:0 spills:fills";
const char* kGateShaderAdrenoLine =
    "FRAG shader: 96 inst, 10 nops, 86 non-nops, 3 half, 8 full, 16 waves, 0 loops";

pb::shaders::StageStatistics gateShaderStage(const char* line) {
    const auto s = pb::shaders::parseStatisticsLine(line);
    EXPECT_TRUE(s.has_value()) << line;
    return s.value_or(pb::shaders::StageStatistics{});
}

// A program of `pass` whose fragment stage reports `inst` instructions (Bifrost's line).
pb::shaders::ProgramStatistics gateShaderProgram(const std::string& pass,
                                                 const std::string& fragment, int inst) {
    pb::shaders::ProgramStatistics p;
    p.pass = pass;
    p.vertex = "fullscreen.vert";
    p.fragment = fragment;
    pb::shaders::StageStatistics f = gateShaderStage(kGateShaderBifrostLine);
    f.fields["inst"] = inst;
    p.stages = {f};
    return p;
}

// mali-g52 as `probebench shaders --no-ablate` reports it for the suite reference, handheld:
// handheld's gi-apply built a stencil mark (40 inst) and the apply shader (132 inst).
pb::shaders::ShaderStatisticsRun gateShaderRun() {
    pb::shaders::TargetStatistics t;
    t.target = "mali-g52";
    t.driver = "panfrost";
    t.programs = {gateShaderProgram("gbuffer", "gbuffer_geometry.frag", 20),
                  gateShaderProgram("gi-apply", "gi_stencil_fill.frag", 40),
                  gateShaderProgram("gi-apply", "gi_ddgi_apply.frag", 132),
                  gateShaderProgram("gi-apply", "gi_ddgi_apply.frag", 180)};
    t.variants = {{"reference", "", "reference", "profile", "", "", {0, 3}},
                  {"handheld", "", "handheld", "profile", "", "", {0, 1, 2}},
                  {"reference@384x216", "", "reference", "reference", "", "", {0, 3}}};
    pb::shaders::TargetStatistics broken;
    broken.target = "adreno-630";
    broken.error = "the shim did not load";
    pb::shaders::ShaderStatisticsRun run;
    run.mesaVersion = "22.3.6-1+deb12u2";
    run.targets = {t, broken};
    return run;
}

const std::vector<std::string> kGateShaderDrivers{"freedreno", "panfrost", "v3d", "nouveau"};

GateRecord gateShaderBaseline() {
    GateRecord r;
    r.suite.camera = "1,2,3,0,0,0,60";
    r.suite.profiles = {"reference", "handheld"};
    r.probes = "10 probes, 1 volumes, rgba16f, fnv1a 0123";
    r.shaders = {shaderRecordOf(gateShaderRun(), kGateShaderDrivers, r.suite.profiles)};
    return r;
}

void gateShaderAdd(ShaderRecord& r, const std::string& profile, const std::string& pass,
                   const std::string& counter, std::int64_t delta) {
    for (ShaderTargetRecord& t : r.targets)
        for (ShaderPassRecord& p : t.passes)
            if (p.profile == profile && p.pass == pass)
                for (auto& [k, v] : p.counters)
                    if (k == counter) v += delta;
}

GateOutcome gateShaderCompare(const GateRecord& base, const ShaderRecord& now,
                              const std::vector<std::string>& problems = {}) {
    GateOutcome o;
    compareShaders(base, now, problems, o);
    return o;
}

const GateRow* gateShaderRow(const GateOutcome& o, const std::string& profile,
                             const std::string& name) {
    for (const GateRow& r : o.rows)
        if (r.group == "shaders" && r.profile == profile && r.name.rfind(name, 0) == 0) return &r;
    return nullptr;
}

bool gateShaderNote(const GateOutcome& o, const std::string& part) {
    for (const std::string& n : o.notes)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

} // namespace

TEST(GateShaderCounters, EveryReportedFigureIsAnExactInteger) {
    const Counters mali = shaderStageCounters(gateShaderStage(kGateShaderBifrostLine));
    const Counters expected{{"instructions", 132}, {"milli_cycles", 4042}, {"spills", 0},
                            {"fills", 0},          {"occupancy", 2},       {"loops", 1}};
    EXPECT_EQ(mali, expected);
    // freedreno: registers full and half and waves, no cycles and no spills reported.
    const Counters adreno = shaderStageCounters(gateShaderStage(kGateShaderAdrenoLine));
    const Counters expectedAdreno{{"instructions", 96},
                                  {"registers_full", 8},
                                  {"registers_half", 3},
                                  {"occupancy", 16},
                                  {"loops", 0}};
    EXPECT_EQ(adreno, expectedAdreno);
    EXPECT_EQ(shaderCounterLabel("milli_cycles"), "mcycles");
}

TEST(GateShaderCounters, ARunBecomesTheSuiteProfilesHeaviestFragmentPerPass) {
    const ShaderRecord r =
        shaderRecordOf(gateShaderRun(), kGateShaderDrivers, {"reference", "handheld"});
    EXPECT_EQ(r.key.mesa, "22.3.6-1+deb12u2");
    EXPECT_EQ(r.key.drivers, kGateShaderDrivers);
    ASSERT_EQ(r.targets.size(), 1u); // adreno-630 failed: left to shaderRunProblems
    const ShaderTargetRecord& t = r.targets[0];
    EXPECT_EQ(t.target, "mali-g52");
    // reference: gbuffer, gi-apply; handheld: gbuffer, gi-apply; "reference@384x216" is not a
    // suite profile.
    ASSERT_EQ(t.passes.size(), 4u);
    ASSERT_NE(t.pass("handheld", "gi-apply"), nullptr);
    EXPECT_EQ(t.pass("handheld", "gi-apply")->counters.front(),
              (std::pair<std::string, std::int64_t>{"instructions", 132})); // not the 40 marks
    EXPECT_EQ(t.pass("reference", "gi-apply")->counters.front().second, 180);
    EXPECT_EQ(t.pass("reference@384x216", "gi-apply"), nullptr);
}

TEST(GateShaderRecord, RoundTripsAndAnOlderBaselineGetsTheDefaultTargets) {
    GateRecord r = gateShaderBaseline();
    r.suite.shaderTargets = {"mali-g52"};
    const nlohmann::json j = recordJson(r);
    EXPECT_EQ(j["suite"]["shader_targets"], nlohmann::json::array({"mali-g52"}));
    EXPECT_EQ(j["shaders"][0]["key"]["mesa"], "22.3.6-1+deb12u2");
    EXPECT_EQ(j["shaders"][0]["targets"]["mali-g52"]["handheld"]["gi-apply"]["instructions"], 132);
    const GateRecord back = recordFromJson(j, "mem");
    EXPECT_EQ(recordJson(back), j);
    ASSERT_NE(back.shadersFor(r.shaders[0].key), nullptr);
    EXPECT_EQ(back.suite.shaderTargets, r.suite.shaderTargets);

    nlohmann::json older = j;
    older.erase("shaders");
    older["suite"].erase("shader_targets");
    const GateRecord old = recordFromJson(older, "mem");
    EXPECT_TRUE(old.shaders.empty());
    EXPECT_EQ(old.suite.shaderTargets,
              (std::vector<std::string>{"adreno-630", "mali-g52", "mali-g57"}));
}

TEST(GateShaderRecord, BadShaderEntriesAreOneLineErrorsNamingTheKey) {
    auto errorOf = [](const nlohmann::json& j) {
        try {
            recordFromJson(j, "b.json");
        } catch (const pb::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const nlohmann::json j = recordJson(gateShaderBaseline());
    nlohmann::json badCounter = j;
    badCounter["shaders"][0]["targets"]["mali-g52"]["handheld"]["gi-apply"]["spills"] = 0.5;
    EXPECT_EQ(errorOf(badCounter),
              "b.json: shaders[0].targets.mali-g52.handheld.gi-apply.spills: must be an integer");
    nlohmann::json noMesa = j;
    noMesa["shaders"][0]["key"].erase("mesa");
    EXPECT_EQ(errorOf(noMesa), "b.json: shaders[0].key.mesa: missing");
    nlohmann::json badTarget = j;
    badTarget["suite"]["shader_targets"] = {"mali-g53"};
    const std::string e = errorOf(badTarget);
    EXPECT_EQ(e.rfind("b.json: suite.shader_targets: unknown shader target 'mali-g53'", 0), 0u)
        << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(GateShaderComparison, TheSameStatisticsPass) {
    const GateRecord base = gateShaderBaseline();
    const GateOutcome o = gateShaderCompare(base, base.shaders[0]);
    EXPECT_EQ(o.rows.size(), 4u);
    for (const GateRow& r : o.rows)
        EXPECT_EQ(r.status, RowStatus::Ok) << r.profile << " " << r.name;
    EXPECT_EQ(o.exitCode(), 0);
    const GateRow* r = gateShaderRow(o, "handheld", "mali-g52 gi-apply");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->name, "mali-g52 gi-apply");
    EXPECT_EQ(r->now, "132/4042/0/0/2/1");
    EXPECT_EQ(r->note, "inst/mcycles/spills/fills/occ/loops");
}

TEST(GateShaderComparison, TenMoreInstructionsFailWithExitThreeNamingWhatMoved) {
    const GateRecord base = gateShaderBaseline();
    ShaderRecord now = base.shaders[0];
    gateShaderAdd(now, "handheld", "gi-apply", "instructions", 10);
    const GateOutcome o = gateShaderCompare(base, now);
    EXPECT_EQ(o.exitCode(), kExitRegression);
    EXPECT_EQ(o.deterministicFailures(), 1);
    const GateRow* r = gateShaderRow(o, "handheld", "mali-g52 gi-apply");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->status, RowStatus::Changed);
    EXPECT_EQ(r->baseline, "132/4042/0/0/2/1");
    EXPECT_EQ(r->now, "142/4042/0/0/2/1");
    EXPECT_EQ(r->note, "inst 132 -> 142 (+10)");
    const std::string table = gateTable(o);
    EXPECT_NE(table.find("CHANGED"), std::string::npos);
    EXPECT_NE(table.find("-- shaders"), std::string::npos);
    EXPECT_NE(table.find("gate: FAIL"), std::string::npos);

    // Any counter: a spill, a milli-cycle.
    for (const char* counter : {"spills", "milli_cycles", "occupancy", "loops"}) {
        ShaderRecord moved = base.shaders[0];
        gateShaderAdd(moved, "reference", "gbuffer", counter, 1);
        EXPECT_EQ(gateShaderCompare(base, moved).exitCode(), kExitRegression) << counter;
    }
}

TEST(GateShaderComparison, AnAppearingOrVanishingPassOrFigureFails) {
    const GateRecord base = gateShaderBaseline();
    ShaderRecord now = base.shaders[0];
    ShaderTargetRecord& t = now.targets[0];
    t.passes.push_back({"handheld", "upsample", {{"instructions", 30}}});
    t.passes.erase(t.passes.begin()); // reference gbuffer
    t.passes[0].counters.emplace_back("local_bytes", 64);
    const GateOutcome o = gateShaderCompare(base, now);
    EXPECT_EQ(gateShaderRow(o, "handheld", "mali-g52 upsample")->status, RowStatus::New);
    EXPECT_EQ(gateShaderRow(o, "reference", "mali-g52 gbuffer")->status, RowStatus::Missing);
    const GateRow* grew = gateShaderRow(o, "reference", "mali-g52 gi-apply");
    EXPECT_EQ(grew->status, RowStatus::Changed);
    EXPECT_EQ(grew->note, "local B - -> 64");
    EXPECT_EQ(o.deterministicFailures(), 3);
    EXPECT_EQ(o.exitCode(), kExitRegression);

    // A whole target in the baseline that this run did not measure.
    ShaderRecord none = base.shaders[0];
    none.targets.clear();
    EXPECT_EQ(gateShaderRow(gateShaderCompare(base, none), "", "mali-g52")->status,
              RowStatus::Missing);
}

TEST(GateShaderComparison, AnotherMesaIsSkippedWithANoteNeverFailed) {
    const GateRecord base = gateShaderBaseline();
    ShaderRecord now = base.shaders[0];
    now.key.mesa = "24.0.1-1";
    gateShaderAdd(now, "handheld", "gi-apply", "instructions", 500);
    const GateOutcome o = gateShaderCompare(base, now);
    EXPECT_EQ(o.exitCode(), 0);
    ASSERT_EQ(o.rows.size(), 1u);
    EXPECT_EQ(o.rows[0].status, RowStatus::Skipped);
    EXPECT_TRUE(gateShaderNote(o, "skipped: baseline has Mesa 22.3.6-1+deb12u2 (freedreno, "
                                  "panfrost, v3d, nouveau), this machine Mesa 24.0.1-1"));
    // Another driver list is another key too.
    now = base.shaders[0];
    now.key.drivers = {"panfrost"};
    EXPECT_EQ(gateShaderCompare(base, now).rows[0].status, RowStatus::Skipped);
}

TEST(GateShaderComparison, ABaselineWithoutShadersIsANoteUntilUpdateRecordsThem) {
    const GateRecord base = gateShaderBaseline();
    GateRecord older = base;
    older.shaders.clear();
    const GateOutcome o = gateShaderCompare(older, base.shaders[0]);
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_TRUE(gateShaderNote(o, "no shader baseline (--update records it)"));
    // --update shows what the baseline gains.
    GateOutcome recording;
    recording.recording = true;
    compareShaders(older, base.shaders[0], {}, recording);
    ASSERT_EQ(recording.rows.size(), 4u);
    EXPECT_EQ(recording.rows[0].status, RowStatus::New);
}

TEST(GateShaderComparison, AFailedTargetIsAFailureWithItsLine) {
    const GateRecord base = gateShaderBaseline();
    ShaderRecord now = base.shaders[0];
    now.targets.clear(); // mali-g52 did not run, so it has no passes
    const GateOutcome o =
        gateShaderCompare(base, now, {"mali-g52: worker exited with status 1: no EGL display"});
    ASSERT_EQ(o.rows.size(), 1u); // not also a MISSING row for each of its passes
    EXPECT_EQ(o.rows[0].status, RowStatus::Failed);
    EXPECT_EQ(o.rows[0].name, "mali-g52");
    EXPECT_EQ(o.rows[0].note, "mali-g52: worker exited with status 1: no EGL display");
    EXPECT_EQ(o.exitCode(), kExitRegression);
    EXPECT_NE(gateTable(o).find("FAILED"), std::string::npos);
}

TEST(GateShaderComparison, CompilersNotBuiltAreANoteExceptOnCiWithAShaderBaseline) {
    const std::string why = "the weak GPUs' compilers are not built (no complete install under "
                            "/x); build them with scripts/mesa-shim.sh (about 10 min on 2 cores)";
    const GateRecord base = gateShaderBaseline();
    GateOutcome here;
    shadersNotBuilt(base, why, false, here);
    EXPECT_EQ(here.exitCode(), 0);
    EXPECT_TRUE(here.rows.empty());
    EXPECT_TRUE(gateShaderNote(here, "scripts/mesa-shim.sh"));

    GateOutcome ci;
    shadersNotBuilt(base, why, true, ci);
    ASSERT_EQ(ci.rows.size(), 1u);
    EXPECT_EQ(ci.rows[0].status, RowStatus::Failed);
    EXPECT_NE(ci.rows[0].note.find("CI=true"), std::string::npos);
    EXPECT_EQ(ci.exitCode(), kExitRegression);

    GateRecord older = base;
    older.shaders.clear();
    GateOutcome ciOlder;
    shadersNotBuilt(older, "not built", true, ciOlder);
    EXPECT_EQ(ciOlder.exitCode(), 0); // nothing to compare against: a note
    EXPECT_TRUE(gateShaderNote(ciOlder, "not built; scripts/mesa-shim.sh builds them"));
}

TEST(GateShaderComparison, OnlyCiEqualToTrueCountsAsCi) {
    const char* old = std::getenv("CI");
    const std::string saved = old ? old : "";
    setenv("CI", "true", 1);
    EXPECT_TRUE(runningOnCi());
    setenv("CI", "1", 1);
    EXPECT_FALSE(runningOnCi());
    unsetenv("CI");
    EXPECT_FALSE(runningOnCi());
    if (old) setenv("CI", saved.c_str(), 1);
}

// The device model's predictions as exact counters (PredictionCounters.h): per pass the time and
// each unit's in whole nanoseconds, and the frame. A change fails on the recording machine; on
// another machine a move within 0.05% (the cache replay's last line) passes with a note.
TEST(GateShaderComparison, ModelRowsAreExactOnTheRecordingMachineAndWithinToleranceElsewhere) {
    pb::bench::DevicePrediction d;
    d.device = "switch-handheld";
    pb::bench::PredictedSession s;
    s.profile = "handheld";
    pb::bench::PredictedVariant v;
    v.id = "handheld";
    v.ms = 3.5452384;
    v.passes.push_back({"gi-apply", "alu", 0.2248144, NAN,
                        {{"predicted_unit_ms",
                          {{"alu", 0.2248144}, {"texture", 0.113608}, {"memory", 0.050195}, {"rop", 0.0084}}}}});
    s.variants.push_back(v);
    d.sessions.push_back(s);
    const ShaderTargetRecord t = predictionRecord(d);
    EXPECT_EQ(t.target, "model:switch-handheld");
    ASSERT_EQ(t.passes.size(), 2u);
    EXPECT_EQ(t.passes[0].counters,
              (Counters{{"predicted_ns", 224814}, {"alu_ns", 224814}, {"texture_ns", 113608},
                        {"memory_ns", 50195}, {"rop_ns", 8400}}));
    EXPECT_EQ(t.passes[1].pass, "frame");
    EXPECT_EQ(t.passes[1].counters, (Counters{{"predicted_ns", 3545238}}));

    GateRecord base;
    base.shaders.push_back({{"22.3.6", {"nouveau"}}, {t}});
    ShaderRecord now = base.shaders[0];
    now.targets[0].passes[0].counters[3].second += 20; // memory_ns: 0.04%
    GateOutcome same;
    compareShaders(base, now, {}, same, false);
    EXPECT_EQ(gateShaderRow(same, "handheld", "model:switch-handheld gi-apply")->status,
              RowStatus::Changed);
    GateOutcome other;
    compareShaders(base, now, {}, other, true);
    const GateRow* row = gateShaderRow(other, "handheld", "model:switch-handheld gi-apply");
    EXPECT_EQ(row->status, RowStatus::Ok);
    EXPECT_NE(row->note.find("within 0.05% on another machine"), std::string::npos) << row->note;
    now.targets[0].passes[0].counters[1].second += 2000; // alu_ns: a shader change, 0.9%
    GateOutcome moved;
    compareShaders(base, now, {}, moved, true);
    EXPECT_EQ(gateShaderRow(moved, "handheld", "model:switch-handheld gi-apply")->status,
              RowStatus::Changed);
}
