// `probebench shaders` as a user runs it: the target list, one-line errors before any work, and
// - where scripts/mesa-shim.sh has built the compilers - every profile's programs compiled by
// the Adreno and Mali compilers, a target whose driver is missing or whose shim does not load
// reported alone while the others still are, and --exec. Without the compilers those tests
// skip, except under CI=true, where CI builds them and their absence is a failure.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace pb::test {
namespace {

namespace fs = std::filesystem;

// The install scripts/mesa-shim.sh made, or "" (the caller skips or, under CI, fails).
std::string shadersInstall() {
    const CommandResult r =
        runCommand({(sourceDir() / "scripts/mesa-shim.sh").string(), "--print"});
    if (r.exitCode != 0) return "";
    std::string dir = r.output;
    while (!dir.empty() && (dir.back() == '\n' || dir.back() == ' '))
        dir.pop_back();
    return dir;
}

#define SHADERS_REQUIRE_COMPILERS(dir)                                                             \
    const std::string dir = shadersInstall();                                                      \
    do {                                                                                           \
        if (dir.empty()) {                                                                         \
            if (underCi()) FAIL() << "the weak GPUs' compilers are not built under CI";            \
            GTEST_SKIP() << "the weak GPUs' compilers are not built (scripts/mesa-shim.sh)";       \
        }                                                                                          \
    } while (0)

nlohmann::json shadersReadJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}

const nlohmann::json* shadersTarget(const nlohmann::json& run, const std::string& name) {
    for (const nlohmann::json& t : run["targets"])
        if (t["target"] == name) return &t;
    return nullptr;
}

// The fragment stage of the heaviest gi-apply program of variant `id` (as the tables pick it).
nlohmann::json shadersGiApply(const nlohmann::json& target, const std::string& id) {
    nlohmann::json best;
    for (const nlohmann::json& v : target["variants"]) {
        if (v["id"] != id) continue;
        for (int i : v["programs"]) {
            const nlohmann::json& p = target["programs"][size_t(i)];
            if (p["pass"] != "gi-apply") continue;
            for (const nlohmann::json& s : p["stages"])
                if (s["stage"] == "fragment" &&
                    (best.is_null() || s["instructions"] > best["instructions"]))
                    best = s;
        }
    }
    return best;
}

const char* kShadersCamera = "0,1.5,0,1,1.2,1,60";

TEST(ShadersCli, ListTargetsNamesEachDeviceItsDriverAndModelId) {
    const CommandResult text = runProbebench({"shaders", "--list-targets"});
    ASSERT_EQ(text.exitCode, 0) << text.output;
    for (const char* s : {"mali-g52", "panfrost", "PAN_GPU_ID=7212", "adreno-630", "FD_GPU_ID=630",
                          "tegra-x1", "NOUVEAU_CHIPSET=12b", "videocore-vi"})
        EXPECT_NE(text.output.find(s), std::string::npos) << s << "\n" << text.output;
    std::string json;
    const CommandResult r = runProbebenchSplit({"shaders", "--list-targets", "--json"},
                                               (outputDir() / "list.json").string(), json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(j.is_object()) << json;
    ASSERT_GE(j["targets"].size(), 10u);
    EXPECT_TRUE(j["targets"][0]["built"].is_boolean());
}

TEST(ShadersCli, AnUnknownTargetIsOneLineBeforeAnyWork) {
    const CommandResult r = runProbebench({"shaders", "--targets", "mali-g25,adreno-630"});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("mali-g25"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("did you mean"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("baking"), std::string::npos) << r.output;
}

TEST(ShadersCli, WithoutTheCompilersItSaysHowToBuildThemBeforeAnyBake) {
    const fs::path out = outputDir(); // once: each call starts a fresh folder
    const fs::path empty = out / "no-install";
    fs::create_directories(empty);
    const CommandResult r =
        runCommand({"env", "-u", "PB_MESA_SHIM_DIR", "PB_MESA_SHIM_ROOT=" + empty.string(),
                    binaryPath().string(), "shaders", "--targets", "mali-g52", "--cache-dir",
                    (out / "cache").string()});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("scripts/mesa-shim.sh"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("baking"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "cache")) << "it baked before saying so";
}

TEST(ShadersCli, EveryProfileOnAdrenoAndMaliWithoutSpillsInTheHandheldGi) {
    SHADERS_REQUIRE_COMPILERS(install);
    const fs::path out = outputDir(); // once: each call starts a fresh folder
    const fs::path probes = bakeNestedRooms(out / "rooms.probes");
    const fs::path json = out / "shaders.json";
    const CommandResult r = runProbebench({"shaders", "--targets", "adreno-630,mali-g52,mali-g57",
                                           "--profiles", "all", "--probes", probes.string(),
                                           "--camera", kShadersCamera, "--json", json.string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("mali-g57: Mali-G57 (Valhall)"), std::string::npos) << r.output;
    const nlohmann::json run = shadersReadJson(json);
    ASSERT_TRUE(run.is_object());
    for (const char* name : {"adreno-630", "mali-g52", "mali-g57"}) {
        const nlohmann::json* t = shadersTarget(run, name);
        ASSERT_TRUE(t) << name;
        EXPECT_FALSE(t->contains("error")) << name << ": " << t->dump();
        EXPECT_GE((*t)["variants"].size(), 5u) << name;
        for (const nlohmann::json& v : (*t)["variants"]) {
            EXPECT_FALSE(v.contains("not_run")) << name << " " << v.dump();
            EXPECT_FALSE(v["programs"].empty()) << name << " " << v["id"];
        }
        for (const nlohmann::json& p : (*t)["programs"]) {
            bool fragment = false;
            for (const nlohmann::json& s : p["stages"])
                fragment = fragment || (s["stage"] == "fragment" && s["instructions"] > 0);
            EXPECT_TRUE(fragment) << name << " " << p.dump();
        }
    }
    // The handheld profile's split loops once spilled on both Malis (bench/shaders/README.md).
    for (const char* mali : {"mali-g52", "mali-g57"}) {
        const nlohmann::json gi = shadersGiApply(*shadersTarget(run, mali), "handheld");
        ASSERT_FALSE(gi.is_null()) << mali;
        EXPECT_EQ(gi["spills"], 0) << mali << " " << gi.dump();
        EXPECT_EQ(gi["fills"], 0) << mali << " " << gi.dump();
    }
    bool loops = false;
    for (const nlohmann::json& p : run["switch_pairs"])
        loops = loops || (p["switch"] == "gi.loops" && p["kind"] == "in_profile");
    EXPECT_TRUE(loops) << run["switch_pairs"].dump();
}

// An install whose `complete` lists freedreno and panfrost (not v3d), with freedreno's shim
// replaced by a file that is no library: the loader ignores it, and the driver finds no device.
fs::path shadersBrokenInstall(const std::string& real, const fs::path& out) {
    const fs::path dir = out / "broken-install";
    fs::create_directories(dir / "lib");
    for (const fs::directory_entry& e : fs::directory_iterator(fs::path(real) / "lib")) {
        const fs::path to = dir / "lib" / e.path().filename();
        if (e.path().filename() == "libfreedreno_noop_drm_shim.so")
            std::ofstream(to) << "not a library";
        else
            fs::create_symlink(e.path(), to);
    }
    std::ofstream(dir / "complete") << "mesa 22.3.6\ndrivers freedreno,panfrost\n";
    return dir;
}

TEST(ShadersCli, AMissingDriverAndABrokenShimFailAloneAndTheOthersAreReported) {
    SHADERS_REQUIRE_COMPILERS(install);
    const fs::path out = outputDir(); // once: each call starts a fresh folder
    const fs::path probes = bakeNestedRooms(out / "rooms.probes");
    const fs::path broken = shadersBrokenInstall(install, out);
    const fs::path json = out / "partial.json";
    const CommandResult r =
        runCommand({"env", "PB_MESA_SHIM_DIR=" + broken.string(), binaryPath().string(), "shaders",
                    "--targets", "adreno-630,mali-g52,videocore-vi", "--profiles", "handheld",
                    "--no-ablate", "--probes", probes.string(), "--camera", kShadersCamera,
                    "--json", json.string(), "--timeout", "120"});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("probebench: shaders: videocore-vi: its driver (v3d) is not in the"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("probebench: shaders: adreno-630: its worker failed"),
              std::string::npos)
        << r.output;
    // Without its shim the driver finds no device: EGL says so (had Mesa fallen back to its
    // software rasterizer instead, the worker refuses that context: "a software renderer").
    EXPECT_NE(r.output.find("adreno-630: its worker failed (exit 1): egl:"), std::string::npos)
        << r.output;
    const nlohmann::json run = shadersReadJson(json);
    ASSERT_TRUE(run.is_object());
    const nlohmann::json* g52 = shadersTarget(run, "mali-g52");
    ASSERT_TRUE(g52);
    EXPECT_FALSE(g52->contains("error")) << g52->dump();
    EXPECT_FALSE(shadersGiApply(*g52, "handheld").is_null());
    EXPECT_TRUE(shadersTarget(run, "adreno-630")->contains("error"));
}

// V3D 4.2 (GLES 3.0) cannot filter 32-bit float textures: rgba32f probes cannot run there. The
// profile is listed as not run with the reason, not failed; Mali runs it.
TEST(ShadersCli, AProfileATargetCannotRunIsListedWithItsReason) {
    SHADERS_REQUIRE_COMPILERS(install);
    const fs::path out = outputDir(); // once: each call starts a fresh folder
    const fs::path probes = out / "rooms32f.probes";
    const CommandResult bake = runProbebench(
        {"bake", "--scene", "rooms", "--volumes", "auto-uniform", "--spacing", "0.8", "--rays",
         "32", "--bounces", "1", "--format", "rgba32f", "--out", probes.string()});
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    const fs::path json = out / "v3d.json";
    const CommandResult r = runProbebench(
        {"shaders", "--targets", "videocore-vi,mali-g52", "--profiles", "reference", "--no-ablate",
         "--probes", probes.string(), "--camera", kShadersCamera, "--json", json.string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("- cannot run reference: rgba32f probes need linear filtering"),
              std::string::npos)
        << r.output;
    const nlohmann::json run = shadersReadJson(json);
    ASSERT_TRUE(run.is_object());
    const nlohmann::json* v3d = shadersTarget(run, "videocore-vi");
    ASSERT_TRUE(v3d);
    ASSERT_FALSE((*v3d)["variants"].empty());
    EXPECT_TRUE((*v3d)["variants"][0].contains("not_run")) << v3d->dump();
    EXPECT_FALSE(shadersGiApply(*shadersTarget(run, "mali-g52"), "reference").is_null());
}

TEST(ShadersCli, ExecRunsACommandOnTheTargetsDriver) {
    SHADERS_REQUIRE_COMPILERS(install);
    std::string json;
    const CommandResult r = runProbebenchSplit(
        {"shaders", "--exec", "mali-g52", "--", binaryPath().string(), "info", "--json"},
        (outputDir() / "info.json").string(), json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    ASSERT_TRUE(j.is_object()) << json;
    EXPECT_EQ(j["renderer"], "Mali-G52 (Panfrost)");
}

} // namespace
} // namespace pb::test
