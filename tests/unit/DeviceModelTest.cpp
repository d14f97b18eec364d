// The device model (bench/devicemodel): device files load and refuse bad input in one line,
// the per-pass arithmetic (largest unit, wide and 3D samples, draws), the compilers' figures
// turned into ALU cycles (Mali's units, instructions over lanes, fp16), the per-pass demand built
// from a cost-model report, and the report's labels and measured pairing. GL-free.
#include "bench/devicemodel/DeviceSpec.h"
#include "bench/devicemodel/FrameDemand.h"
#include "bench/devicemodel/PassModel.h"
#include "bench/devicemodel/ShaderCost.h"
#include "bench/report/DevicePrediction.h"
#include "bench/report/PredictionMeasured.h"
#include "bench/shaders/DriverStatistics.h"
#include "bench/shaders/ShaderTargets.h"
#include "core/Error.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <fstream>

namespace pb::test {
namespace {

namespace dm = devicemodel;

std::vector<std::string> shippedDeviceDirs() { return {(sourceDir() / "profiles" / "devices").string()}; }

// A device with round figures: 2 cores at 1000 MHz, 4 texture units each, 10 GB/s, 8 px/clk.
dm::DeviceSpec roundDevice() {
    dm::DeviceSpec d;
    d.name = "round";
    d.compiler = "tegra-x1";
    d.cores = 2;
    d.clockMhz = 1000;
    d.fp32LanesPerCore = 100;
    d.fp16Rate = 2;
    d.textureUnitsPerCore = 4;
    d.trilinear3dRate = 0.5;
    d.wideTexelRate = 0.5;
    d.ropPixelsPerClock = 8;
    d.drawOverheadUs = 5;
    d.bandwidthGBs = 10;
    d.l2.name = "round L2";
    return d;
}

TEST(DeviceFiles, EveryShippedDeviceLoadsAndNamesAKnownCompiler) {
    const std::vector<std::string> names = dm::deviceNames(shippedDeviceDirs());
    for (const char* required : {"switch-handheld", "switch-docked", "mali-g52-mc2", "mali-g57-mc2",
                                 "adreno-618", "adreno-630", "gtx-1080", "xbox-one", "h200"})
        EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
    for (const std::string& n : names) {
        const dm::DeviceSpec d = dm::findDevice(n, shippedDeviceDirs());
        EXPECT_EQ(d.name, n);
        EXPECT_NO_THROW(shaders::findShaderTarget(d.compiler)) << n;
        EXPECT_GT(d.clockHz(), 0) << n;
        EXPECT_NO_THROW(d.l1.validate()) << n;
        EXPECT_NO_THROW(d.l2.validate()) << n;
        // Every figure carries its source: a comment on its line or on the line above.
        std::ifstream in(d.file);
        std::string line, section;
        bool commentAbove = false;
        while (std::getline(in, line)) {
            if (line.rfind("[", 0) == 0) section = line;
            const bool comment = !line.empty() && line[0] == '#';
            if (!section.empty() && !line.empty() && !comment && line[0] != '[') {
                EXPECT_TRUE(commentAbove || line.find('#') != std::string::npos)
                    << d.file << ": no source for: " << line;
            }
            commentAbove = comment;
        }
    }
    // Docked and handheld differ in the clock only.
    const dm::DeviceSpec docked = dm::findDevice("switch-docked", shippedDeviceDirs());
    const dm::DeviceSpec handheld = dm::findDevice("switch-handheld", shippedDeviceDirs());
    EXPECT_GT(docked.clockMhz, 2 * handheld.clockMhz);
    EXPECT_EQ(docked.cores, handheld.cores);
}

std::string writeDevice(const std::string& stem, const std::string& text) {
    const auto path = outputDir() / (stem + ".toml");
    std::ofstream(path) << text;
    return path.string();
}

const char* kGoodDevice = R"(name = "tiny"
label = "Tiny"
compiler = "mali-g52"
class = "phone"
[gpu]
cores = 1
clock_mhz = 500
fp32_lanes_per_core = 16
fp16_rate = 2.0
texture_units_per_core = 2
trilinear_3d_rate = 0.5
wide_texel_rate = 0.5
rop_pixels_per_clock = 2
draw_overhead_us = 5.0
[memory]
bandwidth_gbs = 8.5
l1_kib = 16
l1_line_bytes = 64
l1_ways = 4
l2_kib = 96
l2_line_bytes = 64
l2_ways = 8
)";

std::string loadError(const std::string& stem, const std::string& text) {
    try {
        dm::loadDevice(writeDevice(stem, text));
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(DeviceFiles, BadFilesAreOneLineErrorsNamingFileAndLine) {
    const dm::DeviceSpec d = dm::loadDevice(writeDevice("tiny", kGoodDevice));
    EXPECT_EQ(d.l2.sizeBytes, 96u * 1024); // 96 KiB: 192 sets, not a power of two
    EXPECT_EQ(d.l2.name, "tiny L2");
    std::string good = kGoodDevice;
    auto with = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        t.replace(t.find(from), from.size(), to);
        return t;
    };
    std::string e = loadError("other", kGoodDevice);
    EXPECT_NE(e.find("other.toml:1:"), std::string::npos) << e;
    EXPECT_NE(e.find("stem"), std::string::npos) << e;
    e = loadError("tiny", with("class = \"phone\"", "class = \"toaster\""));
    EXPECT_NE(e.find("tiny.toml:4:"), std::string::npos) << e;
    e = loadError("tiny", with("clock_mhz = 500", "clock_mhz = -5"));
    EXPECT_NE(e.find("tiny.toml:7:"), std::string::npos) << e;
    EXPECT_NE(e.find("clock_mhz"), std::string::npos) << e;
    e = loadError("tiny", with("fp16_rate = 2.0\n", ""));
    EXPECT_NE(e.find("missing key 'fp16_rate'"), std::string::npos) << e;
    e = loadError("tiny", with("cores = 1", "cores = 1\nshaders = 3"));
    EXPECT_NE(e.find("unknown key 'shaders'"), std::string::npos) << e;
    e = loadError("tiny", with("l2_line_bytes = 64", "l2_line_bytes = 48"));
    EXPECT_NE(e.find("l2 cache"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    try {
        dm::findDevice("switch-handhel", shippedDeviceDirs());
        FAIL() << "no error";
    } catch (const Error& x) {
        EXPECT_NE(std::string(x.what()).find("did you mean 'switch-handheld'"), std::string::npos)
            << x.what();
    }
}

TEST(PassModel, TheLargestUnitBoundsThePassAndDrawsAdd) {
    const dm::DeviceSpec d = roundDevice();
    dm::PassDemand alu;
    alu.pass = "a";
    alu.fragments = 1'000'000;
    alu.aluCyclesPerFragment = 10; // 1e7 cycles over 2 cores at 1 GHz: 5 ms
    alu.samples = 4'000'000;       // 4e6 over 8 units: 0.5 ms
    alu.draws = 2;                 // 10 us
    dm::PassPrediction p = dm::predictPass(d, alu);
    EXPECT_EQ(p.bound, "alu");
    EXPECT_DOUBLE_EQ(p.aluMs, 5.0);
    EXPECT_DOUBLE_EQ(p.textureMs, 0.5);
    EXPECT_DOUBLE_EQ(p.ms, 5.0 + 0.01);

    dm::PassDemand tex;
    tex.samples = 8'000'000;            // 1 ms
    tex.wideSamples = 4'000'000;        // 4e6 / 0.5 = 8e6 unit clocks: 1 ms
    tex.trilinear3dSamples = 2'000'000; // 4e6: 0.5 ms
    tex.wideTrilinear3dSamples = 1'000'000; // 1e6 / 0.25: 0.5 ms
    p = dm::predictPass(d, tex);
    EXPECT_EQ(p.bound, "texture");
    EXPECT_DOUBLE_EQ(p.textureMs, 3.0);

    dm::PassDemand mem;
    mem.bytesRead = 20'000'000;
    mem.bytesWritten = 10'000'000; // 3e7 B at 10 GB/s: 3 ms
    mem.pixelsWritten = 8'000'000; // 1e6 clocks: 1 ms
    p = dm::predictPass(d, mem);
    EXPECT_EQ(p.bound, "memory");
    EXPECT_DOUBLE_EQ(p.memoryMs, 3.0);
    EXPECT_DOUBLE_EQ(p.ropMs, 1.0);

    dm::PassDemand draws;
    draws.draws = 10;
    p = dm::predictPass(d, draws);
    EXPECT_EQ(p.bound, "draws");
    EXPECT_DOUBLE_EQ(p.ms, 0.05);

    const dm::FramePrediction f = dm::predictFrame(d, {alu, tex, mem});
    EXPECT_DOUBLE_EQ(f.totalMs, 5.01 + 3.0 + 3.0);
    EXPECT_EQ(f.pass("a")->bound, "alu");
    EXPECT_EQ(f.pass("missing"), nullptr);
    // Deterministic: the same demand gives the same bits.
    EXPECT_EQ(dm::predictFrame(d, {alu, tex, mem}).toJson().dump(), f.toJson().dump());
}

TEST(ShaderCost, MaliUnitsInstructionsOverLanesAndFp16) {
    dm::DeviceSpec d = roundDevice();
    const auto bifrost = shaders::parseStatisticsLine(
        "MESA_SHADER_FRAGMENT shader: 1461 inst, 900 tuples, 130 clauses, 49.000000 cycles, "
        "30.500000 arith, 12.000000 texture, 0.250000 vary, 49.000000 ldst, 720 quadwords, "
        "1 threads, 0 preloads, 0 loops, 6:43 spills:fills");
    ASSERT_TRUE(bifrost);
    // The largest non-texture unit: the spills' load/store, 49 cycles.
    EXPECT_DOUBLE_EQ(dm::aluCost(*bifrost, "panfrost", d, false).cyclesPerFragment, 49.0);
    // panfrost's counts already hold fp16: no further division.
    EXPECT_DOUBLE_EQ(dm::aluCost(*bifrost, "panfrost", d, true).cyclesPerFragment, 49.0);
    const auto valhall = shaders::parseStatisticsLine(
        "MESA_SHADER_FRAGMENT shader: 846 inst, 6.770000 cycles, 5.000000 fma, 6.770000 cvt, "
        "1.500000 sfu, 0.500000 v, 9.000000 t, 0.000000 ls, 90 quadwords, 1 threads, 1 loops, "
        "0:0 spills:fills");
    ASSERT_TRUE(valhall);
    EXPECT_DOUBLE_EQ(dm::aluCost(*valhall, "panfrost", d, false).cyclesPerFragment, 6.77);
    const auto nouveau = shaders::parseStatisticsLine(
        "type: 1, local: 0, shared: 0, gpr: 15, inst: 500, bytes: 744, cached: 0");
    ASSERT_TRUE(nouveau);
    const dm::AluCost n = dm::aluCost(*nouveau, "nouveau", d, false);
    EXPECT_DOUBLE_EQ(n.cyclesPerFragment, 5.0); // 500 inst / 100 lanes
    EXPECT_NE(n.basis.find("500 inst / 100 lanes"), std::string::npos) << n.basis;
    EXPECT_DOUBLE_EQ(dm::aluCost(*nouveau, "nouveau", d, true).cyclesPerFragment, 2.5);
    d.fp16Rate = 1; // no double rate: fp16 saves nothing
    EXPECT_DOUBLE_EQ(dm::aluCost(*nouveau, "nouveau", d, true).cyclesPerFragment, 5.0);
    EXPECT_EQ(dm::textureInstructions(*nouveau), -1);
    const auto ir3 = shaders::parseStatisticsLine(
        "FRAG shader: 100 inst, 10 nops, 90 non-nops, 2 mov, 4 cov, 200 dwords, 0 last-baryf, "
        "0 half, 8 full, 8 constlen, 10 cat0, 6 cat1, 50 cat2, 20 cat3, 5 cat4, 7 cat5, 0 cat6, "
        "0 cat7, 0 stp, 0 ldp, 0 sstall, 1 (ss), 0 systall, 1 (sy), 16 waves, 0 loops");
    ASSERT_TRUE(ir3);
    EXPECT_EQ(dm::textureInstructions(*ir3), 7);
}

// A cost report of one drawn and one culled volume, replayed through "round L2".
costmodel::CostReport twoVolumeReport() {
    costmodel::CostReport r;
    r.profileVariant = "xyz/fused";
    costmodel::GiPassCounters& c = r.counters;
    c.targetPixels = 1000;
    c.giPixels = 800;
    costmodel::VolumeCounters v;
    v.evaluated = 800;
    v.depthFetches = 1000;
    v.normalFetches = 800;
    v.stateFetches = 6400;
    v.visibilityFetches = 6400;
    v.irradianceFetches = 6400;
    c.volumes.push_back(v);
    costmodel::VolumeCounters culled = v;
    culled.culled = true;
    c.volumes.push_back(culled);
    for (const char* variant : {"xyz/fused", "slice_first/split"}) {
        costmodel::CacheResult res;
        res.variant = variant;
        res.cache.name = "round L2";
        res.cache.lineBytes = 64;
        res.probeLines = 100;
        res.probeHits = std::string(variant) == "xyz/fused" ? 60 : 80;
        res.gbufferLines = 10;
        res.gbufferHits = 0;
        r.results.push_back(res);
    }
    return r;
}

TEST(FrameDemand, TheGiPassComesFromTheReplayAndTheVariantsFetchOrder) {
    const costmodel::CostReport report = twoVolumeReport();
    dm::FrameDemandInputs in;
    in.width = 40;
    in.height = 25; // 1000 pixels
    in.cost = &report;
    in.l2Cache = "round L2";
    in.passes = {"gbuffer", "gi-apply", "direct", "gi-dynamic-sh"};
    in.facts = {25, {}, 3};
    in.programs["gi-apply"] = {12.0, "test", -1};
    in.programs["gbuffer"] = {2.0, "test", 1.0};
    std::vector<dm::PassDemand> d = dm::frameDemand(in);
    ASSERT_EQ(d.size(), 4u);
    const dm::PassDemand& gb = d[0];
    EXPECT_EQ(gb.fragments, 800u); // covered share 800/1000 of 1000 pixels
    EXPECT_EQ(gb.samples, 800u);   // one texture instruction
    EXPECT_EQ(gb.bytesWritten, 25'000u);
    EXPECT_EQ(gb.draws, 3);
    const dm::PassDemand& gi = d[1];
    EXPECT_EQ(gi.fragments, 800u); // the culled volume draws nothing
    EXPECT_EQ(gi.samples, 1000u + 800 + 6400 + 6400);
    EXPECT_EQ(gi.wideSamples, 6400u);
    EXPECT_EQ(gi.bytesRead, (40u + 10) * 64); // xyz/fused's misses
    EXPECT_EQ(gi.bytesWritten, (800u + 1000) * 8); // rgba16f, cleared then written
    EXPECT_EQ(gi.draws, 2);                        // naive: the clear and one volume
    EXPECT_DOUBLE_EQ(gi.aluCyclesPerFragment, 12.0);
    EXPECT_EQ(d[2].aluBasis, "no program statistics");
    EXPECT_EQ(d[3].aluBasis, "not modelled");
    // Slice-first split loops read the same texels in another order: fewer misses.
    in.switches.gi.probeOrder = profile::GiProbeOrder::SliceFirst;
    in.switches.gi.loops = profile::GiLoops::Split;
    in.switches.gi.targetFormat = profile::GiTargetFormat::R11g11b10f;
    d = dm::frameDemand(in);
    EXPECT_EQ(d[1].bytesRead, (20u + 10) * 64);
    EXPECT_EQ(d[1].bytesWritten, (800u + 1000) * 4);
    // A cache the replay did not run is an error, not a zero.
    in.l2Cache = "other L2";
    EXPECT_THROW(dm::frameDemand(in), Error);
}

TEST(DevicePredictionReport, LabelsPredictionsAndPairsMeasurements) {
    bench::DevicePrediction d;
    d.device = "switch-handheld";
    d.label = "Switch";
    bench::PredictedSession s;
    s.profile = "handheld";
    s.width = 64;
    s.height = 36;
    s.ownDevice = true;
    s.budgetMs = 33.3;
    s.ownWidth = 1280;
    s.ownHeight = 720;
    s.ownSizeMs = 40.0;
    s.variants.push_back({"handheld", "handheld", "profile", 2.0, NAN, {{"gi-apply", "alu", 1.5, NAN, {}}}, ""});
    s.variants.push_back({"handheld -gi.loops", "-gi.loops", "reverted", 2.5, NAN, {}, ""});
    s.deltas.push_back({"in_profile", "gi.loops", "fused", "split", "handheld -gi.loops", "handheld", -0.5, NAN});
    d.sessions.push_back(s);
    std::vector<bench::DevicePrediction> all{d};
    EXPECT_TRUE(all[0].sessions[0].overBudget());

    bench::SessionResult measured;
    measured.session.profile.name = "handheld";
    measured.session.variants = {{"handheld", "handheld", bench::VariantRole::Profile, "", {}},
                                 {"handheld -gi.loops", "-gi.loops", bench::VariantRole::Reverted, "gi.loops", {}}};
    measured.variants.resize(2);
    measured.variants[0].variant = measured.session.variants[0];
    measured.variants[0].frameMs.median = 7.0;
    measured.variants[0].sections.push_back({"gi-apply", {}, {}});
    measured.variants[0].sections[0].ms.median = 3.0;
    measured.variants[1].variant = measured.session.variants[1];
    bench::DeltaResult dr;
    dr.planned = {bench::DeltaKind::InProfile, "gi.loops", "fused", "split", 1, 0};
    dr.measured = true;
    dr.ms.estimate = 0.25;
    measured.deltas.push_back(dr);
    bench::attachMeasured(all, {measured});
    EXPECT_DOUBLE_EQ(all[0].sessions[0].variants[0].measuredMs, 7.0);
    EXPECT_DOUBLE_EQ(all[0].sessions[0].variants[0].passes[0].measuredMs, 3.0);
    EXPECT_DOUBLE_EQ(all[0].sessions[0].deltas[0].measuredMs, 0.25);

    const nlohmann::json j = bench::predictionsJson(all);
    EXPECT_EQ(j[0]["model"], "model: switch-handheld");
    EXPECT_EQ(j[0]["sessions"][0]["predicted_over_budget"], true);
    EXPECT_DOUBLE_EQ(j[0]["sessions"][0]["deltas"][0]["predicted_delta_ms"].get<double>(), -0.5);
    EXPECT_DOUBLE_EQ(j[0]["sessions"][0]["deltas"][0]["measured_delta_ms"].get<double>(), 0.25);
    const std::string md = bench::predictionsMarkdown(all);
    EXPECT_NE(md.find("predicted ms (model: switch-handheld)"), std::string::npos) << md;
    EXPECT_NE(md.find("**over**"), std::string::npos) << md;
    // The in-profile row says what reverting does (+0.5 predicted, -0.25 measured): opposite.
    EXPECT_NE(md.find("| handheld | -gi.loops (split -> fused) | +0.500 | -0.250 | opposite |"),
              std::string::npos)
        << md;
    EXPECT_NE(bench::predictionsHtml(all).find("model: switch-handheld"), std::string::npos);
    EXPECT_EQ(bench::predictionsMarkdown({}), "");
}

} // namespace
} // namespace pb::test
