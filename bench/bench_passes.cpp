// Google Benchmark fixtures for every pass of the frame, the whole frame, and the GI pass's
// texture-fetch floor, per platform profile (profiles/*.toml), with manual timing: each
// iteration renders one frame through bench::SectionTimer and reports the pass's exclusive
// time (CPU clock around glFinish on llvmpipe, GL timestamp queries where the driver's are
// trustworthy - the same choice as `probebench bench`). The usual --benchmark_* flags apply
// (--benchmark_filter=handheld, --benchmark_repetitions=5, --benchmark_format=json, ...).
// Own flags, before them: --scene=NAME|FILE (default rooms with bench/volumes/rooms_nested.toml;
// another scene bakes --volumes auto), --volumes=auto|auto-uniform|FILE, --size=WxH (default
// 640x360), --platform=egl|osmesa, --timing=auto|cpu|query.
#include "core/ReuseFreedMemory.h"
#include "bench/runner/FetchFloorPass.h"
#include "bench/runner/ProbeCache.h"
#include "bench/runner/SectionTimer.h"
#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "platforms/Platform.h"
#include "profile/ProfileLoader.h"
#include "scene/SceneLoader.h"
#include "views/WorstCaseView.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <memory>

namespace {

using namespace pb;

struct Options {
    std::string scene = "rooms", platform = "egl", timing = "auto";
    std::string volumes = PB_SOURCE_DIR "/bench/volumes/rooms_nested.toml";
    int width = 640, height = 360;
};

// One profile's renderer, shared by its benchmarks (built once: shader compilation and probe
// upload stay out of the timings).
struct ProfileRig {
    profile::PlatformProfile profile;
    std::unique_ptr<render::FrameRenderer> renderer;
    std::unique_ptr<bench::FetchFloorPass> floor;
    std::string error; // not empty: the renderer rejected the profile
};

struct World {
    Options options;
    std::unique_ptr<platform::Platform> platform;
    scene::Scene scene;
    probes::ProbeSet probes;
    render::RenderView view;
    bench::TimingChoice timing;
    bool es = true;
    std::map<std::string, ProfileRig> rigs;
};

World* world = nullptr;

// Times `frames` of the named section (or the whole frame for "frame", the floor for
// "gi-fetch-floor") of one profile.
void runPass(benchmark::State& state, const std::string& profileName, const std::string& section) {
    ProfileRig& rig = world->rigs.at(profileName);
    if (!rig.error.empty()) {
        state.SkipWithError(rig.error.c_str());
        return;
    }
    bench::SectionTimer timer(world->timing, world->es);
    for (auto _ : state) {
        timer.beginFrame();
        if (section == "gi-fetch-floor") {
            timer.begin("gi-fetch-floor");
            rig.floor->execute(*rig.renderer, world->view);
            timer.end("gi-fetch-floor");
        } else {
            rig.renderer->render(world->view, &timer);
        }
        if (!timer.endFrame()) {
            state.SkipWithError("timer queries reported a disjoint GPU time");
            return;
        }
        double ms = section == "frame" ? timer.frameMs() : 0.0;
        for (const auto& [name, t] : timer.sections())
            if (name == section) ms = t;
        state.SetIterationTime(ms * 1e-3);
    }
    state.counters["pixels"] = double(world->view.width) * world->view.height;
    state.SetLabel(world->timing.name);
}

void parseOwnFlags(int& argc, char** argv, Options& o) {
    int out = 1;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&](const char* flag) -> const char* {
            size_t n = std::strlen(flag);
            return a.compare(0, n, flag) == 0 ? argv[i] + n : nullptr;
        };
        if (const char* v = value("--scene=")) {
            o.scene = v;
            o.volumes = "auto";
        } else if (const char* v = value("--volumes=")) {
            o.volumes = v;
        } else if (const char* v = value("--platform=")) {
            o.platform = v;
        } else if (const char* v = value("--timing=")) {
            o.timing = v;
        } else if (const char* v = value("--size=")) {
            if (std::sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width < 16 || o.height < 16)
                throw Error("--size: expected WxH, e.g. 640x360");
        } else {
            argv[out++] = argv[i];
        }
    }
    argc = out;
}

void setUp(World& w) {
    w.scene = scene::loadScene(w.options.scene, {});
    w.probes = bench::benchProbes(
        w.scene, w.options.volumes, bench::defaultProbeCacheDir(), nullptr,
        [](const std::string& line) { std::fprintf(stderr, "bench_passes: %s\n", line.c_str()); });
    platform::PlatformOptions po;
    po.name = w.options.platform;
    w.platform = platform::createPlatform(po);
    const gl::GlCaps caps = gl::queryCaps();
    w.es = caps.es;
    w.timing = bench::chooseTiming(w.options.timing, caps, gl::detectDriverQuirks());
    scene::View v = views::findWorstCaseView(w.scene, w.probes, 320, 180).view;
    w.view = render::makeRenderView(v, w.scene.worldBounds(), w.options.width, w.options.height);

    profile::ProfileSearch search;
    search.dirs = {PB_PROFILES_DIR};
    for (const std::string& name : profile::profileNames(search)) {
        ProfileRig rig;
        rig.profile = profile::loadProfile(name, search);
        try {
            render::GiOptions gi{&w.probes, 0, rig.profile.switches};
            rig.renderer = std::make_unique<render::FrameRenderer>(
                w.scene, render::defaultFrameSettings(w.scene), gi);
            rig.floor = std::make_unique<bench::FetchFloorPass>(rig.profile.switches);
            for (int i = 0; i < 2; ++i) { // warm-up: shader compilation is not a pass's time
                rig.renderer->render(w.view);
                rig.floor->execute(*rig.renderer, w.view);
            }
        } catch (const Error& e) {
            rig.error = name + ": " + e.what();
            rig.renderer.reset();
            rig.floor.reset();
        }
        std::vector<std::string> sections{"frame", "gi-fetch-floor"};
        if (rig.renderer)
            for (const auto& p : rig.renderer->passes())
                sections.push_back(p->name());
        w.rigs.emplace(name, std::move(rig));
        for (const std::string& section : sections)
            benchmark::RegisterBenchmark(("pass/" + name + "/" + section).c_str(), runPass, name,
                                         section)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
    }
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    World w;
    world = &w;
    try {
        parseOwnFlags(argc, argv, w.options);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
        setUp(w);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_passes: error: %s\n", e.what());
        return 1;
    }
    benchmark::AddCustomContext("scene", w.scene.name);
    benchmark::AddCustomContext("size", std::to_string(w.options.width) + "x" +
                                            std::to_string(w.options.height));
    benchmark::AddCustomContext("timing", w.timing.name + ": " + w.timing.reason);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    w.rigs.clear(); // GL objects go before the context
    return 0;
}
