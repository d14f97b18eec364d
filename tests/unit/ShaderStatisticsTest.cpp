// The weak GPUs' compiler statistics (bench/shaders/): each driver's statistics line parsed as
// Mesa 22.3 writes it, the target table and its environment, the install's `complete` file, the
// JSON a worker hands its parent, and the tables' switch rows. GL-free.
#include "bench/shaders/ShaderStatistics.h"
#include "bench/shaders/DriverStatistics.h"
#include "bench/shaders/MesaShim.h"
#include "bench/shaders/ShaderTables.h"
#include "bench/shaders/ShaderTargets.h"
#include "core/Error.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace pb::test {
namespace {

using shaders::parseStatisticsLine;
using shaders::StageStatistics;

// Lines in each driver's own format (Mesa 22.3.6: ir3_gallium.c, bifrost_compile.c,
// midgard_compile.c, vir.c, nvc0_program.c).
const char* kFreedrenoLine =
    "FRAG shader: 1364 inst, 150 nops, 1214 non-nops, 22 mov, 41 cov, 2900 dwords, "
    "0 last-baryf, 3 half, 16 full, 32 constlen, 151 cat0, 63 cat1, 1092 cat2, 148 cat3, "
    "48 cat4, 26 cat5, 0 cat6, 0 cat7, 0 stp, 0 ldp, 139 sstall, 43 (ss), 40 systall, 11 (sy), "
    "6 waves, 2 loops";
const char* kBifrostLine =
    "MESA_SHADER_FRAGMENT shader: 1461 inst, 900 tuples, 130 clauses, 49.000000 cycles, "
    "30.500000 arith, 12.000000 texture, 0.250000 vary, 49.000000 ldst, 720 quadwords, "
    "1 threads, 0 preloads, 0 loops, 6:43 spills:fills";
const char* kValhallLine =
    "MESA_SHADER_FRAGMENT shader: 846 inst, 6.770000 cycles, 5.000000 fma, 6.770000 cvt, "
    "1.500000 sfu, 0.500000 v, 6.000000 t, 0.000000 ls, 90 quadwords, 1 threads, 1 loops, "
    "0:0 spills:fills";
const char* kMidgardLine = "MESA_SHADER_FRAGMENT shader: 1022 inst, 425 bundles, 786 quadwords, "
                           "16 registers, 1 threads, 0 loops, 4:58 spills:fills";
const char* kV3dLine = "MESA_SHADER_FRAGMENT shader: 726 inst, 2 threads, 2 loops, 40 uniforms, "
                       "70 max-temps, 0:0 spills:fills, 5 sfu-stalls, 731 inst-and-stalls, "
                       "100 nops";
const char* kNouveauLine =
    "type: 4, local: 64, shared: 0, gpr: 53, inst: 519, bytes: 5536, cached: 0";

TEST(ShaderStatisticsParse, FreedrenoLine) {
    const auto s = parseStatisticsLine(kFreedrenoLine);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->stage, "fragment");
    EXPECT_EQ(s->driverStage, "FRAG");
    EXPECT_EQ(s->instructions(), 1364);
    EXPECT_EQ(s->fullRegisters(), 16);
    EXPECT_EQ(s->halfRegisters(), 3);
    EXPECT_EQ(s->occupancy(), 6); // waves
    EXPECT_EQ(s->field("(ss)"), 43);
    EXPECT_EQ(s->field("loops"), 2);
    EXPECT_LT(s->cycles(), 0); // freedreno gives no cycle estimate
    EXPECT_EQ(s->boundUnit(), "");
}

TEST(ShaderStatisticsParse, BifrostLineSplitsSpillsAndNamesTheBoundUnit) {
    const auto s = parseStatisticsLine(kBifrostLine);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->stage, "fragment");
    EXPECT_EQ(s->instructions(), 1461);
    EXPECT_DOUBLE_EQ(s->cycles(), 49.0);
    EXPECT_EQ(s->spills(), 6);
    EXPECT_EQ(s->fills(), 43);
    EXPECT_EQ(s->occupancy(), 1);
    EXPECT_EQ(s->boundUnit(), "ldst");
    ASSERT_EQ(s->unitCycles().size(), 4u);
    EXPECT_EQ(s->unitCycles()[1].first, "texture");
}

TEST(ShaderStatisticsParse, ValhallMidgardV3dAndNouveauLines) {
    const auto valhall = parseStatisticsLine(kValhallLine);
    ASSERT_TRUE(valhall);
    EXPECT_EQ(valhall->boundUnit(), "cvt");
    EXPECT_EQ(valhall->unitCycles().size(), 6u);
    EXPECT_EQ(valhall->spills(), 0);

    const auto midgard = parseStatisticsLine(kMidgardLine);
    ASSERT_TRUE(midgard);
    EXPECT_EQ(midgard->fullRegisters(), 16);
    EXPECT_EQ(midgard->fills(), 58);

    const auto v3d = parseStatisticsLine(kV3dLine);
    ASSERT_TRUE(v3d);
    EXPECT_EQ(v3d->fullRegisters(), 70); // max-temps
    EXPECT_EQ(v3d->occupancy(), 2);
    EXPECT_EQ(v3d->field("inst-and-stalls"), 731);

    const auto nv = parseStatisticsLine(kNouveauLine);
    ASSERT_TRUE(nv);
    EXPECT_EQ(nv->stage, "fragment"); // gallium's PIPE_SHADER_FRAGMENT is 4
    EXPECT_EQ(nv->fullRegisters(), 53);
    EXPECT_EQ(nv->instructions(), 519);
    EXPECT_EQ(nv->field("local"), 64);
    EXPECT_EQ(shaders::spillsFills(&*nv), "64 B local");
}

TEST(ShaderStatisticsParse, VertexStagesOfEachDriver) {
    EXPECT_EQ(parseStatisticsLine("VERT shader: 20 inst, 2 nops, 4 full, 1 waves")->stage,
              "vertex");
    EXPECT_EQ(parseStatisticsLine("MESA_SHADER_POSITION shader: 12 inst, 1 threads")->stage,
              "vertex");
    EXPECT_EQ(parseStatisticsLine("MESA_SHADER_VARYING shader: 9 inst, 1 threads")->stage,
              "vertex-varying");
    EXPECT_EQ(parseStatisticsLine("type: 0, local: 0, shared: 0, gpr: 6, inst: 20, bytes: 216, "
                                  "cached: 0")
                  ->stage,
              "vertex");
}

TEST(ShaderStatisticsParse, OtherDriverMessagesAreNotStatistics) {
    for (const char* text :
         {"FRAG shader: recompiling at draw time: global 0x00000000, vfsamples 0/0, astc 0/0",
          "performance: glReadPixels is slow", "", "shader: 12 inst", "Two words shader: 12 inst",
          "type: fragment, gpr: high", "MESA_SHADER_FRAGMENT shader: 12 bananas x"})
        EXPECT_FALSE(parseStatisticsLine(text)) << text;
}

TEST(ShaderTargetsTable, NamesAreUniqueAndListsParse) {
    const auto& all = shaders::shaderTargets();
    std::vector<std::string> names;
    for (const auto& t : all)
        names.push_back(t.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
    for (const char* wanted : {"adreno-530", "adreno-618", "adreno-630", "mali-g31", "mali-g52",
                               "mali-g57", "mali-g72", "mali-t860", "videocore-vi", "tegra-x1"})
        EXPECT_TRUE(std::binary_search(names.begin(), names.end(), wanted)) << wanted;
    EXPECT_EQ(shaders::parseShaderTargets("all").size(), all.size());
    const auto two = shaders::parseShaderTargets("mali-g52,adreno-630,mali-g52");
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].name, "mali-g52");
    EXPECT_EQ(two[1].name, "adreno-630");
}

TEST(ShaderTargetsTable, UnknownNamesAndEmptyItemsAreOneLineErrors) {
    try {
        shaders::parseShaderTargets("mali-g25");
        FAIL() << "accepted mali-g25";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("mali-g25"), std::string::npos) << m;
        EXPECT_NE(m.find("did you mean"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    EXPECT_THROW(shaders::parseShaderTargets("mali-g52,,adreno-630"), Error);
}

// A fake install folder: `complete` naming `drivers`, and the shim files given.
std::filesystem::path shaderFakeInstall(const std::string& drivers,
                                        const std::vector<std::string>& shims) {
    const auto dir = outputDir() / "install";
    std::filesystem::create_directories(dir / "lib");
    std::ofstream(dir / "complete")
        << "mesa 22.3.6-1+deb12u2\ndrivers " << drivers << "\nbuilt 2026-12-02T00:00:00Z\n";
    for (const std::string& s : shims)
        std::ofstream(dir / "lib" / s) << "x";
    return dir;
}

TEST(MesaShimInstall, CompleteFileAndWhatEachTargetNeeds) {
    const auto dir = shaderFakeInstall("panfrost,v3d", {"libpanfrost_noop_drm_shim.so"});
    const shaders::MesaShimInstall install = shaders::readMesaShim(dir.string());
    EXPECT_EQ(install.mesaVersion, "22.3.6-1+deb12u2");
    EXPECT_EQ(install.drivers, (std::vector<std::string>{"panfrost", "v3d"}));
    const auto& g52 = shaders::findShaderTarget("mali-g52");
    EXPECT_EQ(shaders::targetUnavailableReason(g52, install), "");
    const std::string fd =
        shaders::targetUnavailableReason(shaders::findShaderTarget("adreno-630"), install);
    EXPECT_NE(fd.find("freedreno"), std::string::npos) << fd;
    const std::string v3d =
        shaders::targetUnavailableReason(shaders::findShaderTarget("videocore-vi"), install);
    EXPECT_NE(v3d.find("libv3d_noop_drm_shim.so"), std::string::npos) << v3d;

    const std::vector<std::string> env = shaders::targetEnvironment(g52, install);
    const auto has = [&](const std::string& e) {
        return std::find(env.begin(), env.end(), e) != env.end();
    };
    EXPECT_TRUE(has("LD_PRELOAD=" + (dir / "lib" / "libpanfrost_noop_drm_shim.so").string()));
    EXPECT_TRUE(has("GALLIUM_THREAD=0"));
    EXPECT_TRUE(has("MESA_SHADER_CACHE_DISABLE=true"));
    EXPECT_TRUE(has("PAN_GPU_ID=7212"));
    EXPECT_TRUE(has("LIBGL_DRIVERS_PATH=" + (dir / "lib" / "dri").string()));
}

TEST(MesaShimInstall, AnIncompleteFolderIsAnErrorNamingIt) {
    const auto dir = outputDir() / "half-built";
    std::filesystem::create_directories(dir);
    try {
        shaders::readMesaShim(dir.string());
        FAIL() << "accepted a folder without 'complete'";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("scripts/mesa-shim.sh"), std::string::npos);
    }
}

// Two variants of one profile that differ in one switch: the off one's gi-apply program has
// spills, the on one's none; both share the gbuffer program.
shaders::ShaderStatisticsRun shaderRunWithOnePair() {
    shaders::ShaderStatisticsRun run;
    shaders::TargetStatistics t;
    t.target = "mali-g52";
    t.driver = "panfrost";
    const auto program = [](const char* pass, const char* frag, const char* defines,
                            const char* line) {
        shaders::ProgramStatistics p;
        p.pass = pass;
        p.vertex = "fullscreen.vert";
        p.fragment = frag;
        p.defines = defines;
        p.stages.push_back(*parseStatisticsLine(line));
        return p;
    };
    t.programs.push_back(
        program("gbuffer", "gbuffer_geometry.frag", "",
                "MESA_SHADER_FRAGMENT shader: 94 inst, 2.4 cycles, 2.4 arith, "
                "0 texture, 0 vary, 0 ldst, 2 threads, 0 loops, 0:0 spills:fills"));
    t.programs.push_back(program("gi-apply", "gi_ddgi_apply.frag", "GI_LOOPS_FUSED", kBifrostLine));
    t.programs.push_back(
        program("gi-apply", "gi_ddgi_apply.frag", "GI_LOOPS_SPLIT",
                "MESA_SHADER_FRAGMENT shader: 802 inst, 21.4 cycles, 21.4 arith, "
                "6 texture, 0 vary, 0 ldst, 1 threads, 1 loops, 0:0 spills:fills"));
    shaders::VariantStatistics off{"p -gi.loops", "-gi.loops", "p",   "reverted",
                                   "gi.loops",    "",          {0, 1}};
    shaders::VariantStatistics on{"p", "p", "p", "profile", "", "", {0, 2}};
    t.variants = {on, off};
    run.targets.push_back(t);
    run.pairs.push_back({"p", "in_profile", "gi.loops", "fused", "split", "p -gi.loops", "p"});
    run.pairs.push_back({"p", "in_profile", "gi.upsample", "a", "a", "p", "p"});
    return run;
}

TEST(ShaderTables, ASwitchRowShowsOnlyThePassesItChanges) {
    const shaders::ShaderStatisticsRun run = shaderRunWithOnePair();
    const auto rows = shaders::switchRows(run, run.targets[0]);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].pass, "gi-apply");
    EXPECT_EQ(rows[0].offFragment->spills(), 6);
    EXPECT_EQ(rows[0].onFragment->spills(), 0);
    EXPECT_EQ(shaders::change(rows[0].offFragment->instructions(),
                              rows[0].onFragment->instructions(), false),
              "-659");
    EXPECT_EQ(rows[1].pass, ""); // the same programs on both sides: no program changes

    const auto passes = shaders::passRows(run.targets[0]);
    ASSERT_EQ(passes.size(), 2u); // the profile variant only: gbuffer, gi-apply
    EXPECT_EQ(passes[1].program->defines, "GI_LOOPS_SPLIT");

    const std::string md = shaders::shaderMarkdown(run);
    EXPECT_NE(md.find("| in p | gi.loops | fused -> split | gi-apply | -659 |"), std::string::npos)
        << md;
    EXPECT_NE(md.find("6:43 -> 0:0"), std::string::npos) << md;
}

TEST(ShaderStatisticsJson, RoundTripsAndRejectsAProgramIndexOutOfRange) {
    const shaders::ShaderStatisticsRun run = shaderRunWithOnePair();
    const nlohmann::json j = shaders::toJson(run.targets[0]);
    const shaders::TargetStatistics back = shaders::targetStatisticsFromJson(j);
    ASSERT_EQ(back.programs.size(), 3u);
    EXPECT_EQ(back.programs[1].stages[0].fields, run.targets[0].programs[1].stages[0].fields);
    EXPECT_EQ(back.variants[1].programs, (std::vector<int>{0, 1}));
    EXPECT_EQ(j["programs"][1]["stages"][0]["spills"], 6);
    EXPECT_EQ(j["programs"][1]["stages"][0]["bound_unit"], "ldst");

    nlohmann::json bad = j;
    bad["variants"][0]["programs"] = {0, 7};
    EXPECT_THROW(shaders::targetStatisticsFromJson(bad), Error);
    EXPECT_THROW(shaders::targetStatisticsFromJson(nlohmann::json{{"programs", 3}}), Error);
}

TEST(ShaderTables, ATargetThatDidNotRunSaysWhyInTheMarkdown) {
    shaders::ShaderStatisticsRun run;
    shaders::TargetStatistics t;
    t.target = "adreno-630";
    t.error = "its driver (freedreno) is not in the install";
    run.targets.push_back(t);
    const std::string md = shaders::shaderMarkdown(run);
    EXPECT_NE(md.find("**Not run:** its driver (freedreno)"), std::string::npos) << md;
}

} // namespace
} // namespace pb::test
