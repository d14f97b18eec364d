// bench_bake: the Embree probe bake, measured against bare Embree on the SAME rays in the
// same run (see bench/README.md "Probe bake"). Not a test: nothing here asserts a time.
//
//   BM_BakeVsEmbree   one iteration = a full bake (sponza_decimated, one 32x8x32 volume, 256
//                     rays, 2 bounces, all cores) followed by a replay of exactly the rays that
//                     bake traced through rtcIntersect1 / rtcOccluded1 with nothing else
//                     around them (twice; the faster counts). Use --benchmark_repetitions=N: bake
//                     and replay alternate (A B A B ...), and every repetition reports its own
//                     ratio.
//   BM_SamplerLookup  the CPU reference sampler on the baked data, random points/normals.
//
// Scene: $PB_SPONZA_GLB, else $PB_SCENES_DIR/sponza_decimated/sponza_s_lod4.glb, else
// ../shared/scenes beside the source tree.
#include "core/ReuseFreedMemory.h"
#include "probes/bake/BakePhaseClock.h"
#include "probes/bake/Baker.h"
#include "core/ParallelFor.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace {

using namespace pb::probes;
using pb::parallelFor;
using pb::resolveThreadCount;
using Clock = std::chrono::steady_clock;

std::string sponzaPath() {
    if (const char* p = std::getenv("PB_SPONZA_GLB")) return p;
    std::filesystem::path dir =
        std::filesystem::path(__FILE__).parent_path() / "../../shared/scenes";
    if (const char* d = std::getenv("PB_SCENES_DIR")) dir = d;
    return (dir / "sponza_decimated/sponza_s_lod4.glb").string();
}

// The volume of renderer/probes/examples/sponza_32x8x32.toml.
ProbeVolume sponzaVolume() {
    ProbeVolume v;
    v.name = "sponza";
    v.center = {1.875f, 8.815f, 0.5f};
    v.halfExtents = {18.0f, 9.8f, 9.8f};
    v.counts = {32, 8, 32};
    return v;
}

struct Setup {
    pb::scene::Scene scene;
    BakeRequest request;
    ProbeSet baked;
    std::vector<pb::raytrace::RecordedRay> rays; // primary first, then shadow rays
    std::size_t primary = 0;
};

Setup& setup() {
    static Setup s = [] {
        Setup out;
        out.scene = pb::scene::loadScene(sponzaPath());
        out.request.volumes = {sponzaVolume()};
        out.request.scenarios = resolveScenarios({}, {}, out.scene);
        out.request.settings.raysPerProbe = 256;
        out.request.settings.bounces = 2;
        out.request.recordRays = &out.rays;
        out.baked = bakeProbes(out.scene, out.request); // also the warm-up run
        out.request.recordRays = nullptr;
        std::stable_partition(out.rays.begin(), out.rays.end(),
                              [](const pb::raytrace::RecordedRay& r) { return !r.shadow; });
        for (const pb::raytrace::RecordedRay& r : out.rays)
            out.primary += r.shadow ? 0 : 1;
        return out;
    }();
    return s;
}

struct ReplayTime {
    double wall, cpu; // cpu: all threads of the process
};

// Bare Embree over [begin, end) of the recorded rays, on `threads` threads.
ReplayTime replay(RTCScene scene, const std::vector<pb::raytrace::RecordedRay>& rays, std::size_t begin,
                  std::size_t end, int threads) {
    const std::size_t chunk = 1024, items = (end - begin + chunk - 1) / chunk;
    auto t0 = Clock::now();
    const double cpu0 = BakePhaseClock::processCpuSeconds();
    // One cache line per thread (as the bake's counters): a shared line would slow the replay.
    std::vector<pb::PerThread<unsigned>> sink(static_cast<size_t>(threads));
    parallelFor(items, threads, [&](std::size_t item, int t) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        std::size_t lo = begin + item * chunk, hi = std::min(end, lo + chunk);
        for (std::size_t i = lo; i < hi; ++i) {
            const pb::raytrace::RecordedRay& r = rays[i];
            RTCRayHit rh;
            rh.ray.org_x = r.origin.x, rh.ray.org_y = r.origin.y, rh.ray.org_z = r.origin.z;
            rh.ray.dir_x = r.dir.x, rh.ray.dir_y = r.dir.y, rh.ray.dir_z = r.dir.z;
            rh.ray.tnear = r.tnear, rh.ray.tfar = r.tfar, rh.ray.time = 0.0f;
            rh.ray.mask = 0xFFFFFFFFu, rh.ray.id = 0, rh.ray.flags = 0;
            if (r.shadow) {
                rtcOccluded1(scene, &ctx, &rh.ray);
                sink[size_t(t)].value += rh.ray.tfar < 0.0f;
            } else {
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene, &ctx, &rh);
                sink[size_t(t)].value += rh.hit.geomID;
            }
        }
    });
    benchmark::DoNotOptimize(sink.data());
    return {std::chrono::duration<double>(Clock::now() - t0).count(),
            BakePhaseClock::processCpuSeconds() - cpu0};
}

void BM_BakeVsEmbree(benchmark::State& state) {
    Setup& s = setup();
    const int threads = resolveThreadCount(0);
    pb::raytrace::RayScene raw(s.scene); // same static geometry, same build quality as the bake's
    for (auto _ : state) {
        BakeStats st;
        ProbeSet set = bakeProbes(s.scene, s.request, &st);
        benchmark::DoNotOptimize(set.irradiance.data());
        // The replay twice, the faster one kept: bare Embree's throughput is what it can do,
        // and another process on the cores only ever slows a run down. (This makes the
        // fraction lower, never higher, than one replay would.)
        auto fastest = [&](std::size_t begin, std::size_t end) {
            const ReplayTime a = replay(raw.handle(), s.rays, begin, end, threads);
            const ReplayTime b = replay(raw.handle(), s.rays, begin, end, threads);
            return a.wall <= b.wall ? a : b;
        };
        const ReplayTime primaryTime = fastest(0, s.primary);
        const ReplayTime shadowTime = fastest(s.primary, s.rays.size());
        const double rawPrimary = primaryTime.wall, rawShadow = shadowTime.wall;
        state.SetIterationTime(st.seconds);
        const double primary = double(st.primaryRays), all = primary + double(st.shadowRays);
        state.counters["bake_s"] = st.seconds;
        state.counters["bvh_s"] = st.buildSeconds;
        state.counters["trace_s"] = st.traceSeconds;
        state.counters["raw_primary_s"] = rawPrimary;
        state.counters["raw_shadow_s"] = rawShadow;
        state.counters["bake_Mrays_s"] = all / st.traceSeconds * 1e-6;
        state.counters["raw_intersect1_Mrays_s"] = primary / rawPrimary * 1e-6;
        // The bake's rays/s over bare Embree's on the same rays: all rays (primary through
        // rtcIntersect1 + shadow through rtcOccluded1), and primary rays only.
        state.counters["fraction_all_rays"] = (rawPrimary + rawShadow) / st.traceSeconds;
        state.counters["fraction_primary"] = rawPrimary / st.traceSeconds;
        // The same ratio in CPU seconds (all threads): robust against other processes on
        // the cores, but blind to idle threads (a serial step costs the bake wall time, not
        // CPU time), so fraction_all_rays stays the figure of the target.
        state.counters["trace_cpu_s"] = st.traceCpuSeconds;
        state.counters["raw_cpu_s"] = primaryTime.cpu + shadowTime.cpu;
        state.counters["fraction_cpu"] = (primaryTime.cpu + shadowTime.cpu) / st.traceCpuSeconds;
        // What the bake does besides tracing, in CPU: its tracing time less bare Embree's on
        // the same rays, in total and per ray (primary + shadow). The part of the bake that is
        // its own work, whatever share Embree takes on a given CPU.
        const double ownCpu = st.traceCpuSeconds - (primaryTime.cpu + shadowTime.cpu);
        state.counters["own_cpu_s"] = ownCpu;
        state.counters["own_cpu_ns_per_ray"] = ownCpu / all * 1e9;
        // Where the bake's tracing went (Baker.h, BakePhase): wall and process CPU seconds
        // (CPU < threads x wall: a thread waited at the phase's barrier or for the cores).
        for (const BakePhase& ph : st.phases) {
            state.counters["phase_" + ph.name + "_s"] = ph.wallSeconds;
            state.counters["phase_" + ph.name + "_cpu_s"] = ph.cpuSeconds;
        }
        state.counters["rays"] = primary;
        state.counters["shadow_rays"] = double(st.shadowRays);
        state.counters["threads"] = threads;
    }
}
BENCHMARK(BM_BakeVsEmbree)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

// range(0) = 0: points in random order (every lookup touches new probes, as scattered bake
// hits do); 1: the same points sorted along x (neighbouring lookups share probes).
void BM_SamplerLookup(benchmark::State& state) {
    Setup& s = setup();
    ProbeSampler sampler(s.baked, 0);
    const ProbeVolume& v = s.baked.volumes[0];
    std::uint64_t rng = 42;
    const size_t n = 1 << 16;
    std::vector<glm::vec3> points(n), normals(n);
    for (size_t i = 0; i < n; ++i) {
        points[i] = v.toWorld(
            (glm::vec3(uniformFloat(rng), uniformFloat(rng), uniformFloat(rng)) * 2.0f - 1.0f) *
            v.halfExtents);
        normals[i] = glm::normalize(
            glm::vec3(uniformFloat(rng), uniformFloat(rng), uniformFloat(rng)) - 0.5f);
    }
    if (state.range(0) == 1) {
        glm::vec3 cell = v.cellSize();
        auto key = [&](const glm::vec3& p) {
            glm::ivec3 c = glm::ivec3((v.toLocal(p) + v.halfExtents) / cell);
            return (c.y * 64 + c.z) * 64 + c.x;
        };
        std::sort(points.begin(), points.end(),
                  [&](const glm::vec3& a, const glm::vec3& b) { return key(a) < key(b); });
    }
    size_t i = 0;
    for (auto _ : state) {
        IrradianceSample r = sampler.sample(points[i], normals[i], normals[i]);
        benchmark::DoNotOptimize(r);
        i = (i + 1) & (n - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SamplerLookup)->Arg(0)->Arg(1);

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    benchmark::Initialize(&argc, argv);
    if (!std::filesystem::exists(sponzaPath())) {
        std::cerr << "bench_bake: scene not found: " << sponzaPath()
                  << " (set PB_SPONZA_GLB or PB_SCENES_DIR)\n";
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
