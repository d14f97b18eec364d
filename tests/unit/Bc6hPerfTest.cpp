// BC6H encoder throughput and error on probe-like data of the size the brief names: a
// 32x8x32 probe volume = 8 slices of 256x256 irradiance (8x8 octahedral tiles) and 8 slices
// of 512x512 visibility (16x16 tiles, mean distance and mean squared distance). A benchmark,
// not a test: it asserts nothing about time and is disabled by default. Run it with
//   build/tests/unit_tests --gtest_filter='Bc6hPerf.*' --gtest_also_run_disabled_tests
// (PB_BC6H_QUALITY=fast|normal|high picks the quality, default normal).
#include "probes/bc6h/Bc6h.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
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

Bc6hQuality qualityFromEnv() {
    const char* q = std::getenv("PB_BC6H_QUALITY");
    const std::string s = q ? q : "normal";
    return s == "fast" ? Bc6hQuality::Fast : s == "high" ? Bc6hQuality::High : Bc6hQuality::Normal;
}

TEST(Bc6hPerf, DISABLED_EncodeProbeVolume) {
    const Bc6hQuality q = qualityFromEnv();
    double seconds[2] = {}, meanRel[2] = {}, maxRel[2] = {};
    std::size_t texels[2] = {};
    for (int slice = 0; slice < 8; ++slice) {
        const std::vector<float> data[2] = {irradianceSlice(slice), visibilitySlice(slice)};
        const int sizes[2] = {256, 512}, strides[2] = {3, 2};
        for (int k = 0; k < 2; ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            const std::vector<std::uint8_t> blocks =
                encodeBc6hUf16(data[k].data(), sizes[k], sizes[k], strides[k], q);
            seconds[k] +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            texels[k] += static_cast<std::size_t>(sizes[k]) * sizes[k];
            const std::vector<float> out = decodeBc6hUf16(blocks.data(), sizes[k], sizes[k]);
            // Floors: 1e-3 of irradiance level ~1; 1 cm of distance (1e-4 m^2 for d^2).
            const Bc6hErrorStats e = measureBc6hError(data[k].data(), strides[k], out.data(),
                                                      sizes[k], sizes[k], k == 0 ? 1e-3 : 1e-2);
            meanRel[k] += e.meanRel / 8.0;
            maxRel[k] = std::max(maxRel[k], e.maxRel);
        }
    }
    const char* names[2] = {"irradiance 8 x 256x256 RGB", "visibility 8 x 512x512 RG"};
    for (int k = 0; k < 2; ++k)
        std::printf("%-28s %6.2f s  %5.2f Mtexel/s  rel. error mean %.4f max %.4f\n", names[k],
                    seconds[k], texels[k] / seconds[k] / 1e6, meanRel[k], maxRel[k]);
    std::printf("%-28s %6.2f s  %5.2f Mtexel/s\n", "total", seconds[0] + seconds[1],
                (texels[0] + texels[1]) / (seconds[0] + seconds[1]) / 1e6);
}

} // namespace
