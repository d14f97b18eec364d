// bench_guards: what the numerical guards (gi.guard_exposure, gi.guard_clamp) cost per frame.
// A benchmark, not a test: it prints a table and asserts nothing (studies/findings/guards.md, "Guards").
//
// The stress room (renderer/stress/StressScene.h, probes 9x5x9, 64 rays) at --width x --height
// (default 960x540), exposure 1e-3 so the exposure guard really scales (2^-9). For each base
// profile (defaults: fp32 + rgba16f target; handheld-like: fp16 + r11g11b10f + half) four
// configurations - both guards off, exposure only, clamp only, both - are rendered
// interleaved: every round renders each configuration --frames times (CPU clock around the
// frame and glFinish; llvmpipe finishes the work at glFinish) and keeps the median. The cost
// of a configuration is the Hodges-Lehmann shift of its round medians against "off" with a
// 95% Wilcoxon interval (pb_metrics). The first frame of every configuration compiles
// shaders and is not counted.
//
//   build/studies/bench_guards [--width W --height H --rounds N --frames N]
//
// Under valgrind --tool=callgrind with LP_NUM_THREADS=0 and --only CONFIG --rounds 1 the
// instruction count of one configuration is repeatable (DESIGN.md): a hardware-independent
// proxy (studies/findings/guards.md, "Guards", lists the command).
#include "core/ReuseFreedMemory.h"
#include "frame/FrameRenderer.h"
#include "metrics/Statistics.h"
#include "platforms/Platform.h"
#include "stress/StressScene.h"
#include "studies/common/StudyBake.h"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h> // only marks the measured frames (no-ops outside valgrind)
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace pb;

namespace {

// The command line (usage above).
struct Options {
    int width = 960, height = 540;
    int rounds = 9, frames = 3;
    std::string only; // --only BASE/GUARDS, e.g. "defaults/both": that configuration alone
};

struct Config {
    std::string base, name;
    profile::Profile profile;
};

// The stress room and its probes: what every configuration renders.
struct StressRoom {
    stress::StressScene scene;
    probes::ProbeSet probes;
};

int intArg(int argc, char** argv, const char* name, int def) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], name) == 0) return std::atoi(argv[i + 1]);
    return def;
}

Options parseOptions(int argc, char** argv) {
    Options o;
    o.width = intArg(argc, argv, "--width", 960);
    o.height = intArg(argc, argv, "--height", 540);
    o.rounds = std::max(1, intArg(argc, argv, "--rounds", 9));
    o.frames = std::max(1, intArg(argc, argv, "--frames", 3));
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--only") == 0) o.only = argv[i + 1];
    return o;
}

// Both base profiles x the four guard settings, in table order (each base's "off" first).
std::vector<Config> configs() {
    std::vector<Config> out;
    const std::vector<std::pair<std::string, std::vector<std::string>>> bases = {
        {"defaults", {}},
        {"handheld-like",
         {"gi.precision=fp16", "gi.target_format=r11g11b10f", "gi.resolution=half"}}};
    const std::vector<std::pair<std::string, std::pair<const char*, const char*>>> guards = {
        {"off", {"off", "off"}},
        {"exposure", {"on", "off"}},
        {"clamp", {"off", "on"}},
        {"both", {"on", "on"}}};
    for (const auto& [base, sets] : bases)
        for (const auto& [name, g] : guards) {
            Config c{base, name, {}};
            for (const std::string& s : sets)
                c.profile.applyOverride(s);
            c.profile.set("gi.guard_exposure", g.first);
            c.profile.set("gi.guard_clamp", g.second);
            out.push_back(c);
        }
    return out;
}

// configs(), or only the one --only names.
std::vector<Config> selectedConfigs(const std::string& only) {
    std::vector<Config> all = configs();
    if (!only.empty())
        all.erase(std::remove_if(all.begin(), all.end(),
                                 [&](const Config& c) { return c.base + "/" + c.name != only; }),
                  all.end());
    return all;
}

// The stress room (probes 9x5x9), lit 1e3 times brighter so that exposure 1e-3 makes the
// exposure guard really scale (2^-9), baked with 64 rays.
StressRoom bakeStressRoom() {
    stress::StressSceneParams params;
    params.probeCounts = glm::ivec3(9, 5, 9);
    params.lightScale = 1e3; // exposure 1e-3: the exposure guard scales by 2^-9
    StressRoom room{stress::makeStressScene(params), {}};
    studies::BakeOptions bake;
    bake.volumes = {room.scene.volume};
    bake.scenarios = {"day"};
    bake.rays = 64;
    room.probes = studies::bake(room.scene.scene, bake);
    return room;
}

// One renderer per configuration, each warmed up with one frame (it compiles the shaders).
std::vector<std::unique_ptr<render::FrameRenderer>>
warmedUpRenderers(const StressRoom& room, const std::vector<Config>& configs,
                  const render::RenderView& view) {
    const render::FrameSettings settings = render::defaultFrameSettings(room.scene.scene);
    std::vector<std::unique_ptr<render::FrameRenderer>> renderers;
    for (const Config& c : configs) {
        render::GiOptions gi;
        gi.probes = &room.probes;
        gi.profile = c.profile;
        renderers.push_back(
            std::make_unique<render::FrameRenderer>(room.scene.scene, settings, gi));
        renderers.back()->render(view); // compiles the shaders: not counted
        glFinish();
    }
    return renderers;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Per configuration, the median frame ms of every round; each round renders every
// configuration `frames` times in turn (CPU clock around the frame and glFinish).
std::vector<std::vector<double>>
timeInterleavedRounds(const std::vector<std::unique_ptr<render::FrameRenderer>>& renderers,
                      const render::RenderView& view, int rounds, int frames) {
    std::vector<std::vector<double>> ms(renderers.size());
    CALLGRIND_START_INSTRUMENTATION;
    for (int r = 0; r < rounds; ++r)
        for (std::size_t c = 0; c < renderers.size(); ++c) {
            std::vector<double> t;
            for (int f = 0; f < frames; ++f) {
                const auto t0 = std::chrono::steady_clock::now();
                renderers[c]->render(view);
                glFinish();
                t.push_back(
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                        .count());
            }
            ms[c].push_back(median(t));
        }
    CALLGRIND_STOP_INSTRUMENTATION;
    return ms;
}

// The table: per configuration its median, and against its base's "off" the paired shift of
// the round medians with its 95% interval (from 2 rounds on).
void printTable(const Options& o, const platform::Platform& platform,
                const std::vector<Config>& all, const std::vector<std::vector<double>>& ms) {
    std::printf("bench_guards: stress room %dx%d, %s, %d rounds x %d frames, interleaved\n",
                o.width, o.height, platform.description().c_str(), o.rounds, o.frames);
    std::printf("%-14s %-9s %10s %28s\n", "base", "guards", "median ms", "vs off: ms [95% CI]");
    for (std::size_t c = 0; c < all.size(); ++c) {
        std::printf("%-14s %-9s %10.2f", all[c].base.c_str(), all[c].name.c_str(), median(ms[c]));
        std::size_t off = c - c % 4;
        if (c % 4 != 0 && off < all.size() && all[off].name == "off" && o.rounds >= 2) {
            const stats::Shift d = stats::pairedShift(ms[off], ms[c]);
            std::printf(" %+9.2f [%+.2f, %+.2f]", d.estimate, d.ciLow, d.ciHigh);
        }
        std::printf("\n");
    }
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
    platform::PlatformOptions po;
    auto platform = platform::createPlatform(po);
    const StressRoom room = bakeStressRoom();
    const render::RenderView view =
        render::makeRenderView(room.scene.view, room.scene.scene.worldBounds(), o.width, o.height);
    const std::vector<Config> all = selectedConfigs(o.only);
    const auto renderers = warmedUpRenderers(room, all, view);
    const std::vector<std::vector<double>> ms =
        timeInterleavedRounds(renderers, view, o.rounds, o.frames);
    printTable(o, *platform, all, ms);
    return 0;
}
