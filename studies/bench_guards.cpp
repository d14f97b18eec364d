// bench_guards: what the numerical guards (gi.guard_exposure, gi.guard_clamp) cost per frame.
// A benchmark, not a test: it prints a table and asserts nothing (bench/README.md, "Guards").
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
//   build/bench/bench_guards [--width W --height H --rounds N --frames N]
//
// Under valgrind --tool=callgrind with LP_NUM_THREADS=0 and --only CONFIG --rounds 1 the
// instruction count of one configuration is repeatable (DESIGN.md): a hardware-independent
// proxy (bench/README.md lists the command).
#include "core/ReuseFreedMemory.h"
#include "frame/FrameRenderer.h"
#include "metrics/Statistics.h"
#include "platforms/Platform.h"
#include "probes/bake/Baker.h"
#include "stress/StressScene.h"

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

struct Config {
    std::string base, name;
    profile::Profile profile;
};

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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

int intArg(int argc, char** argv, const char* name, int def) {
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], name) == 0) return std::atoi(argv[i + 1]);
    return def;
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const int width = intArg(argc, argv, "--width", 960);
    const int height = intArg(argc, argv, "--height", 540);
    const int rounds = std::max(1, intArg(argc, argv, "--rounds", 9));
    const int frames = std::max(1, intArg(argc, argv, "--frames", 3));
    std::string only;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--only") == 0) only = argv[i + 1]; // "defaults/both"

    platform::PlatformOptions po;
    auto platform = platform::createPlatform(po);
    stress::StressSceneParams params;
    params.probeCounts = glm::ivec3(9, 5, 9);
    params.lightScale = 1e3; // exposure 1e-3: the exposure guard scales by 2^-9
    const stress::StressScene s = stress::makeStressScene(params);
    probes::BakeRequest req;
    req.volumes = {s.volume};
    req.scenarios = probes::resolveScenarios({"day"}, {}, s.scene);
    req.settings.raysPerProbe = 64;
    const probes::ProbeSet set = probes::bakeProbes(s.scene, req);
    render::FrameSettings settings = render::defaultFrameSettings(s.scene);
    const render::RenderView view =
        render::makeRenderView(s.view, s.scene.worldBounds(), width, height);

    std::vector<Config> all = configs();
    if (!only.empty())
        all.erase(std::remove_if(all.begin(), all.end(),
                                 [&](const Config& c) { return c.base + "/" + c.name != only; }),
                  all.end());
    std::vector<std::unique_ptr<render::FrameRenderer>> renderers;
    for (const Config& c : all) {
        render::GiOptions gi;
        gi.probes = &set;
        gi.profile = c.profile;
        renderers.push_back(std::make_unique<render::FrameRenderer>(s.scene, settings, gi));
        renderers.back()->render(view); // compiles the shaders: not counted
        glFinish();
    }
    std::vector<std::vector<double>> ms(all.size());
    CALLGRIND_START_INSTRUMENTATION;
    for (int r = 0; r < rounds; ++r)
        for (std::size_t c = 0; c < all.size(); ++c) {
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

    std::printf("bench_guards: stress room %dx%d, %s, %d rounds x %d frames, interleaved\n", width,
                height, platform->description().c_str(), rounds, frames);
    std::printf("%-14s %-9s %10s %28s\n", "base", "guards", "median ms", "vs off: ms [95% CI]");
    for (std::size_t c = 0; c < all.size(); ++c) {
        std::printf("%-14s %-9s %10.2f", all[c].base.c_str(), all[c].name.c_str(), median(ms[c]));
        std::size_t off = c - c % 4;
        if (c % 4 != 0 && off < all.size() && all[off].name == "off" && rounds >= 2) {
            const stats::Shift d = stats::pairedShift(ms[off], ms[c]);
            std::printf(" %+9.2f [%+.2f, %+.2f]", d.estimate, d.ciLow, d.ciHigh);
        }
        std::printf("\n");
    }
    return 0;
}
