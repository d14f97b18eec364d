// The gate's baseline records and verdicts (bench/gate): a JSON round trip, one-line errors
// naming the file and key, every exact counter change failing (exit 3) until the baseline is
// updated, accuracy within tolerances, the model-vs-GL agreement, callgrind baselines keyed by
// toolchain (another key: skipped with a note, never a failure), and the exit codes.
#include "bench/gate/GateRecord.h"
#include "bench/gate/CallgrindOutput.h"
#include "bench/gate/GateOutcome.h"
#include "core/Error.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

using namespace pb::gate;
namespace fs = std::filesystem;

namespace {

GateRecord sampleRecord() {
    GateRecord r;
    r.suite.camera = "1,2,3,0,0,0,60";
    r.suite.profiles = {"reference", "handheld"};
    r.probes = "10 probes, 1 volumes, rgba16f, fnv1a 0123";
    ProfileRecord ref;
    ref.name = "reference";
    ref.counters = {{"gl.shadow.draws", 16},
                    {"gl.shadow.programs", 1},
                    {"model.gi.evaluated.house", 1000},
                    {"model.gi_pixels", 1000}};
    ref.glPixels = {{"house", 1001}};
    ProfileRecord hh;
    hh.name = "handheld";
    hh.counters = {{"gl.shadow.draws", 16},         {"model.gi.evaluated.house", 250},
                   {"cache.preset.line_bytes", 64}, {"cache.xyz/fused.lines", 5000},
                   {"cache.xyz/fused.hits", 4900},  {"model.gi_pixels", 250}};
    hh.glPixels = {{"house", 250}};
    hh.accuracy = {true, 0.0176, 34.1, 0.065};
    hh.ratioSamples = {0.74, 0.75, 0.73};
    r.profiles = {ref, hh};
    CallgrindRecord cg;
    cg.key = {"Mesa 22.3.6", "15.0.6", "GCC 12.2.0", "valgrind-3.19.0"};
    cg.profiles = {{"reference", {{"frame", 1000000}, {"shadow", 400000}, {"gi-apply", 600000}}}};
    r.callgrind = {cg};
    return r;
}

GateOutcome gateRecordCompare(const GateRecord& base, const GateRecord& now) {
    GateOutcome o;
    compareRecords(base, now, o);
    return o;
}

const GateRow* gateRecordRow(const GateOutcome& o, const std::string& profile,
                             const std::string& name) {
    for (const GateRow& r : o.rows)
        if (r.profile == profile && r.name.rfind(name, 0) == 0) return &r;
    return nullptr;
}

void setCounter(GateRecord& r, const std::string& profile, const std::string& key, std::int64_t v) {
    for (ProfileRecord& p : r.profiles)
        if (p.name == profile)
            for (auto& [k, value] : p.counters)
                if (k == key) value = v;
}

std::string errorOf(const nlohmann::json& j) {
    try {
        recordFromJson(j, "b.json");
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(GateRecord, JsonRoundTripKeepsEverything) {
    const GateRecord r = sampleRecord();
    const nlohmann::json j = recordJson(r);
    const GateRecord back = recordFromJson(j, "mem");
    EXPECT_EQ(recordJson(back), j);
    EXPECT_EQ(back.profile("handheld")->ratioSamples, r.profile("handheld")->ratioSamples);
    ASSERT_NE(back.callgrindFor(r.callgrind[0].key), nullptr);
    // An identical image's PSNR (+inf) is stored as null and read back as +inf.
    GateRecord inf = r;
    inf.profiles[1].accuracy.psnr = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(std::isinf(recordFromJson(recordJson(inf), "mem").profiles[1].accuracy.psnr));
}

TEST(GateRecord, WriteAndReadAFile) {
    const fs::path p = pb::test::outputDir() / "b.json";
    writeGateRecord(p.string(), sampleRecord());
    EXPECT_EQ(recordJson(readGateRecord(p.string())), recordJson(sampleRecord()));
}

TEST(GateRecord, BadFilesAreOneLineErrorsNamingFileAndKey) {
    nlohmann::json j = recordJson(sampleRecord());
    nlohmann::json wrongSchema = j;
    wrongSchema["schema"] = "probebench.gate/0";
    EXPECT_EQ(errorOf(wrongSchema),
              "b.json: schema: 'probebench.gate/0', expected 'probebench.gate/1'");
    nlohmann::json noCamera = j;
    noCamera["suite"].erase("camera");
    EXPECT_EQ(errorOf(noCamera), "b.json: suite.camera: missing");
    nlohmann::json badCounter = j;
    badCounter["profiles"][0]["counters"]["gl.shadow.draws"] = "16";
    EXPECT_EQ(errorOf(badCounter),
              "b.json: profiles[0].counters.gl.shadow.draws: must be an integer");
    nlohmann::json badTiming = j;
    badTiming["suite"]["timing"]["min_rounds"] = 1;
    EXPECT_NE(errorOf(badTiming).find("b.json: suite.timing: "), std::string::npos);
    for (const std::string& e :
         std::vector<std::string>{errorOf(wrongSchema), errorOf(noCamera), errorOf(badCounter)})
        EXPECT_EQ(e.find('\n'), std::string::npos);

    const fs::path dir = pb::test::outputDir();
    std::ofstream(dir / "not.json") << "{ nope";
    EXPECT_THROW(
        {
            try {
                readGateRecord((dir / "not.json").string());
            } catch (const pb::Error& e) {
                EXPECT_EQ(std::string(e.what()), (dir / "not.json").string() + ": not valid JSON");
                throw;
            }
        },
        pb::Error);
    EXPECT_THROW(readGateRecord((dir / "missing.json").string()), pb::Error);
}

TEST(GateOutcome, TheSameMeasurementsPass) {
    const GateOutcome o = gateRecordCompare(sampleRecord(), sampleRecord());
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_EQ(o.deterministicFailures(), 0);
    for (const GateRow& r : o.rows)
        EXPECT_FALSE(failsDeterministic(r.status)) << r.profile << " " << r.name;
    EXPECT_NE(gateTable(o).find("gate: PASS"), std::string::npos);
}

TEST(GateOutcome, AnyChangedCounterFailsWithExitThree) {
    for (const char* key :
         {"gl.shadow.draws", "model.gi.evaluated.house", "cache.xyz/fused.hits"}) {
        GateRecord now = sampleRecord();
        setCounter(now, "handheld", key, 1 + now.profile("handheld")->counter(key)[0]);
        const GateOutcome o = gateRecordCompare(sampleRecord(), now);
        EXPECT_EQ(o.exitCode(), kExitRegression) << key;
        EXPECT_EQ(o.deterministicFailures(), 1) << key;
        const std::string table = gateTable(o);
        EXPECT_NE(table.find("CHANGED"), std::string::npos);
        EXPECT_NE(table.find("gate: FAIL"), std::string::npos);
    }
    // Grouped counters name the field that moved.
    GateRecord now = sampleRecord();
    setCounter(now, "reference", "gl.shadow.programs", 2);
    const GateOutcome changed = gateRecordCompare(sampleRecord(), now); // outlives the row pointer
    const GateRow* r = gateRecordRow(changed, "reference", "gl.shadow");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->status, RowStatus::Changed);
    EXPECT_EQ(r->baseline, "16/1");
    EXPECT_EQ(r->now, "16/2");
    EXPECT_EQ(r->note, "programs +1");
}

TEST(GateOutcome, NewAndMissingCountersFailLikeChangedOnes) {
    GateRecord now = sampleRecord();
    now.profiles[0].counters.emplace_back("gl.new-pass.draws", 1);
    now.profiles[1].counters.erase(now.profiles[1].counters.begin()); // gl.shadow.draws
    const GateOutcome o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(gateRecordRow(o, "reference", "gl.new-pass")->status, RowStatus::New);
    EXPECT_EQ(gateRecordRow(o, "handheld", "gl.shadow")->status, RowStatus::Missing);
    EXPECT_EQ(o.exitCode(), kExitRegression);
}

TEST(GateOutcome, ChangedProbeDataIsNamed) {
    GateRecord now = sampleRecord();
    now.probes = "10 probes, 1 volumes, rgba16f, fnv1a 4567";
    const GateOutcome o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(gateRecordRow(o, "", "probe data")->status, RowStatus::Changed);
}

TEST(GateOutcome, AccuracyWithinToleranceLossBeyondIt) {
    GateRecord now = sampleRecord();
    now.profiles[1].accuracy.relMseGi = 0.065 * 1.2;    // within +25%
    now.profiles[1].accuracy.flipMean = 0.0176 + 0.001; // within +10% of 0.0176
    GateOutcome o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(o.exitCode(), 0);
    EXPECT_EQ(gateRecordRow(o, "handheld", "rel. MSE")->status, RowStatus::Ok);

    now.profiles[1].accuracy.relMseGi = 0.065 * 1.3; // past +25%
    o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(gateRecordRow(o, "handheld", "rel. MSE")->status, RowStatus::Worse);
    EXPECT_EQ(o.exitCode(), kExitRegression);

    now = sampleRecord();
    now.profiles[1].accuracy.psnr = 34.1 - 0.6; // PSNR may fall 0.5 dB
    EXPECT_EQ(gateRecordRow(gateRecordCompare(sampleRecord(), now), "handheld", "PSNR")->status,
              RowStatus::Worse);

    now = sampleRecord();
    now.profiles[1].accuracy.flipMean = 0.01; // better: passes, suggests an update
    o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(gateRecordRow(o, "handheld", "FLIP")->status, RowStatus::Better);
    EXPECT_EQ(o.exitCode(), 0);
}

TEST(GateOutcome, ModelAndGlPixelsMustAgree) {
    GateRecord now = sampleRecord();
    EXPECT_EQ(
        gateRecordRow(gateRecordCompare(sampleRecord(), now), "reference", "evaluated px, house")
            ->status,
        RowStatus::Ok); // 1 pixel apart
    now.profiles[0].glPixels = {{"house", 1010}};
    const GateOutcome o = gateRecordCompare(sampleRecord(), now);
    EXPECT_EQ(gateRecordRow(o, "reference", "evaluated px, house")->status, RowStatus::Disagree);
    EXPECT_EQ(o.exitCode(), kExitRegression);
}

TEST(GateOutcome, TimingRegressionsAloneExitFour) {
    GateOutcome o = gateRecordCompare(sampleRecord(), sampleRecord());
    TimingComparison slower;
    slower.verdict = TimingVerdict::Different;
    slower.shift = 0.05;
    slower.baselineMedian = 10;
    slower.candidateMedian = 10.5;
    o.rows.push_back(timingRow("handheld", "frame ms", slower, "ms", 9, false));
    EXPECT_EQ(o.rows.back().status, RowStatus::Slower);
    EXPECT_EQ(o.exitCode(), kExitTimingRegression);
    TimingComparison unknown;
    unknown.baselineMedian = 10;
    o.rows.back() = timingRow("handheld", "frame ms", unknown, "ms", 30, true);
    EXPECT_EQ(o.rows.back().status, RowStatus::Unknown);
    EXPECT_NE(o.rows.back().note.find("budget reached"), std::string::npos);
    EXPECT_EQ(o.exitCode(), 0); // undecided is reported, not failed
}

TEST(GateCallgrind, AnotherToolchainsBaselineIsSkippedNotFailed) {
    CallgrindRecord now = sampleRecord().callgrind[0];
    now.key.mesa = "Mesa 24.0.1";
    now.profiles[0].second[0].second = 2000000; // would be far off
    GateOutcome o;
    compareCallgrind(sampleRecord(), now, o);
    ASSERT_EQ(o.rows.size(), 1u);
    EXPECT_EQ(o.rows[0].status, RowStatus::Skipped);
    ASSERT_EQ(o.notes.size(), 1u);
    EXPECT_NE(o.notes[0].find("Mesa 24.0.1"), std::string::npos);
    EXPECT_NE(o.notes[0].find("Mesa 22.3.6"), std::string::npos);
    EXPECT_EQ(o.exitCode(), 0);
}

TEST(GateCallgrind, TheSameToolchainIsGatedWithinTheTolerance) {
    const GateRecord base = sampleRecord(); // tolerance 0.5% of the frame
    CallgrindRecord now = base.callgrind[0];
    now.profiles[0].second = {{"frame", 1004000}, {"shadow", 404000}, {"gi-apply", 600000}};
    GateOutcome ok;
    compareCallgrind(base, now, ok);
    EXPECT_EQ(ok.rows[0].status, RowStatus::Ok);
    now.profiles[0].second = {{"frame", 1010000}, {"shadow", 400000}, {"gi-apply", 610000}};
    GateOutcome worse;
    compareCallgrind(base, now, worse);
    EXPECT_EQ(worse.rows[0].status, RowStatus::Worse);
    EXPECT_NE(worse.rows[0].note.find("gi-apply +10000"), std::string::npos);
    EXPECT_EQ(worse.exitCode(), kExitRegression);
}

TEST(GateCallgrind, DumpsFoldIntoProfilesAndSections) {
    const fs::path dir = pb::test::outputDir();
    auto write = [&](const std::string& name, const std::string& trigger, long long ir) {
        std::ofstream(dir / name) << "version: 1\ncreator: callgrind-3.19.0\npart: 1\n"
                                  << "desc: Trigger: " << trigger << "\nevents: Ir\nsummary: " << ir
                                  << "\n\nfn=(1) main\n0 " << ir << "\ntotals: " << ir << "\n";
    };
    write("cg.out.1", "Client Request: handheld/(outside)", 10);
    write("cg.out.2", "Client Request: handheld/shadow", 300);
    write("cg.out.3", "Client Request: handheld/(outside)", 5);
    write("cg.out.4", "Client Request: reference/shadow", 200);
    write("cg.out", "Program termination", 99);
    std::vector<CallgrindDump> dumps;
    for (const char* f : {"cg.out.1", "cg.out.2", "cg.out.3", "cg.out.4", "cg.out"})
        dumps.push_back(readCallgrindDump((dir / f).string()));
    EXPECT_EQ(dumps[1].trigger, "handheld/shadow");
    EXPECT_EQ(dumps[4].trigger, "");
    const auto profiles = callgrindProfiles(dumps);
    ASSERT_EQ(profiles.size(), 2u);
    EXPECT_EQ(profiles[0].first, "handheld");
    const Counters expected{{"frame", 315}, {"(outside)", 15}, {"shadow", 300}};
    EXPECT_EQ(profiles[0].second, expected);
    EXPECT_EQ(profiles[1].second.front(), (std::pair<std::string, std::int64_t>{"frame", 200}));
    std::ofstream(dir / "cut") << "desc: Trigger: Client Request: x/y\n";
    EXPECT_THROW(readCallgrindDump((dir / "cut").string()), pb::Error);
}

TEST(GateCallgrind, TheKeyComesFromTheGlStringsCompilerAndValgrind) {
    const CallgrindKey k =
        callgrindKey("OpenGL ES 3.2 Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)", "GCC 12.2.0",
                     "valgrind-3.19.0");
    EXPECT_EQ(k.mesa, "Mesa 22.3.6");
    EXPECT_EQ(k.llvm, "15.0.6");
    EXPECT_EQ(k.text(), "Mesa 22.3.6, LLVM 15.0.6, GCC 12.2.0, valgrind-3.19.0");
    EXPECT_EQ(callgrindKey("4.6.0 NVIDIA 535.54", "NVIDIA GeForce", "", "").llvm, "unknown");
}
