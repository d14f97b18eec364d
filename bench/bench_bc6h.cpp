// bench_bc6h: BC6H encoder throughput and error on probe-like data of the size the brief names:
// a 32x8x32 probe volume = 8 slices of 256x256 irradiance (8x8 octahedral tiles) and 8 slices
// of 512x512 visibility (16x16 tiles, mean distance and mean squared distance). Not a test:
// nothing here asserts a time.
//
//   BM_Bc6hEncode/KIND/QUALITY   one iteration = the 8 slices of one kind (0 irradiance RGB,
//                                1 visibility RG) encoded at one quality (0 fast, 1 normal,
//                                2 high). Counters: texels/s, and the relative error of the
//                                decoded slices (mean over slices, max), measured once outside
//                                the timing.
//
//   build/bench/bench_bc6h --benchmark_filter='BM_Bc6hEncode/.*/1'   # normal quality only
#include "probes/bc6h/Bc6h.h"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstddef>
#include <vector>

namespace {

using namespace pb::probes;

void octahedralDirection(float u, float v, float d[3]) {
    float x = u * 2.0f - 1.0f, y = v * 2.0f - 1.0f;
    const float z = 1.0f - std::fabs(x) - std::fabs(y);
    if (z < 0.0f) {
        const float ox = x;
        x = (1.0f - std::fabs(y)) * (ox >= 0.0f ? 1.0f : -1.0f);
        y = (1.0f - std::fabs(ox)) * (y >= 0.0f ? 1.0f : -1.0f);
    }
    const float len = std::sqrt(x * x + y * y + z * z);
    d[0] = x / len;
    d[1] = y / len;
    d[2] = z / len;
}

// Irradiance of a sky (brighter above), a sun lobe max(0, n.l) that some probes do not see,
// and a warm bounce from below; levels vary by probe over ~3 decades.
std::vector<float> irradianceSlice(int slice) {
    const int probes = 32, tile = 8, w = probes * tile;
    std::vector<float> img(static_cast<std::size_t>(w) * w * 3);
    for (int py = 0; py < probes; ++py) {
        for (int px = 0; px < probes; ++px) {
            const float level =
                std::pow(10.0f, -1.5f + 3.0f * (0.5f + 0.5f * std::sin(px * 0.37f + slice) *
                                                           std::cos(py * 0.23f)));
            const bool sunVisible = (px * 7 + py * 3 + slice) % 5 != 0;
            const float sun[3] = {0.48f, 0.36f, 0.8f};
            for (int y = 0; y < tile; ++y) {
                for (int x = 0; x < tile; ++x) {
                    float n[3];
                    octahedralDirection((x + 0.5f) / tile, (y + 0.5f) / tile, n);
                    const float sky = 0.6f + 0.4f * n[2];
                    const float lit =
                        sunVisible ? std::max(0.0f, n[0] * sun[0] + n[1] * sun[1] + n[2] * sun[2])
                                   : 0.0f;
                    const float bounce = 0.5f - 0.5f * n[2];
                    float* p =
                        &img[((static_cast<std::size_t>(py) * tile + y) * w + px * tile + x) * 3];
                    p[0] = level * (0.20f * sky + 3.0f * lit + 0.30f * bounce);
                    p[1] = level * (0.25f * sky + 2.8f * lit + 0.20f * bounce);
                    p[2] = level * (0.45f * sky + 2.4f * lit + 0.10f * bounce);
                }
            }
        }
    }
    return img;
}

// Distance from each probe to the walls of a 16 x 4 x 16 room with a pillar every 3 m:
// smooth inside faces, hard edges at the pillars (the case two-region blocks are for).
std::vector<float> visibilitySlice(int slice) {
    const int probes = 32, tile = 16, w = probes * tile;
    std::vector<float> img(static_cast<std::size_t>(w) * w * 2);
    for (int py = 0; py < probes; ++py) {
        for (int px = 0; px < probes; ++px) {
            const float o[3] = {px * 0.5f + 0.25f, slice * 0.5f + 0.3f, py * 0.5f + 0.2f};
            const float hi[3] = {16.0f, 4.0f, 16.0f};
            const float c[3] = {std::floor(o[0] / 3.0f) * 3.0f + 1.5f, 1.0f,
                                std::floor(o[2] / 3.0f) * 3.0f + 1.5f};
            for (int y = 0; y < tile; ++y) {
                for (int x = 0; x < tile; ++x) {
                    float d[3];
                    octahedralDirection((x + 0.5f) / tile, (y + 0.5f) / tile, d);
                    float t = 1e9f;
                    for (int a = 0; a < 3; ++a)
                        if (std::fabs(d[a]) > 1e-6f)
                            t = std::min(
                                t, std::max(((d[a] > 0 ? hi[a] : 0.0f) - o[a]) / d[a], 0.01f));
                    float oc[3], b = 0.0f, cc = -0.49f;
                    for (int a = 0; a < 3; ++a) {
                        oc[a] = o[a] - c[a];
                        b += oc[a] * d[a];
                        cc += oc[a] * oc[a];
                    }
                    if (b * b - cc > 0.0f) {
                        const float hit = -b - std::sqrt(b * b - cc);
                        if (hit > 0.0f) t = std::min(t, hit);
                    }
                    float* p =
                        &img[((static_cast<std::size_t>(py) * tile + y) * w + px * tile + x) * 2];
                    p[0] = t;
                    p[1] = t * t * 1.05f; // a filtered E[d^2] sits a little above E[d]^2
                }
            }
        }
    }
    return img;
}

constexpr int kSlices = 8;

struct Kind {
    std::vector<std::vector<float>> slices;
    int size, stride;
    double errorFloor; // 1e-3 of irradiance level ~1; 1 cm of distance (1e-4 m^2 for d^2)
};

Kind makeKind(std::vector<float> (*slice)(int), int size, int stride, double errorFloor) {
    Kind d{{}, size, stride, errorFloor};
    for (int s = 0; s < kSlices; ++s)
        d.slices.push_back(slice(s));
    return d;
}

// The data is deterministic and costly to build: made once per kind, outside the timing.
const Kind& kind(int k) {
    static const Kind kinds[2] = {makeKind(&irradianceSlice, 256, 3, 1e-3),
                                  makeKind(&visibilitySlice, 512, 2, 1e-2)};
    return kinds[k];
}

void BM_Bc6hEncode(benchmark::State& state) {
    const Kind& d = kind(int(state.range(0)));
    const Bc6hQuality q = state.range(1) == 0   ? Bc6hQuality::Fast
                          : state.range(1) == 2 ? Bc6hQuality::High
                                                : Bc6hQuality::Normal;
    std::vector<std::vector<std::uint8_t>> blocks(kSlices);
    for (auto _ : state)
        for (int s = 0; s < kSlices; ++s) {
            blocks[size_t(s)] =
                encodeBc6hUf16(d.slices[size_t(s)].data(), d.size, d.size, d.stride, q);
            benchmark::DoNotOptimize(blocks[size_t(s)].data());
        }
    double meanRel = 0.0, maxRel = 0.0;
    for (int s = 0; s < kSlices; ++s) {
        const std::vector<float> out = decodeBc6hUf16(blocks[size_t(s)].data(), d.size, d.size);
        const Bc6hErrorStats e = measureBc6hError(d.slices[size_t(s)].data(), d.stride, out.data(),
                                                  d.size, d.size, d.errorFloor);
        meanRel += e.meanRel / kSlices;
        maxRel = std::max(maxRel, e.maxRel);
    }
    state.SetItemsProcessed(state.iterations() * kSlices * d.size * d.size); // texels
    state.counters["rel_error_mean"] = meanRel;
    state.counters["rel_error_max"] = maxRel;
}
BENCHMARK(BM_Bc6hEncode)
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->ArgNames({"kind", "quality"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
