// ProbeConvolution adds each texel's weighted rays in the order of its weight row
// (irradianceRow), whatever it runs side by side for speed: the baked tiles' bits depend on
// it. Checked against a plain loop over each row, one texel at a time, on ray sets whose rows
// have many different lengths (and, at 3 rays, texels that fall back to their nearest ray).
#include "core/Luminance.h"
#include "probes/ProbeLayout.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RayDirections.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace pb::probes;

namespace {

// Radiance that differs in every ray and channel, with magnitudes far apart, so that a sum in
// another order rounds differently.
std::vector<float> radiance(std::size_t rays, std::uint64_t seed) {
    std::vector<float> rgbx;
    for (std::size_t r = 0; r < rays; ++r) {
        for (int ch = 0; ch < 3; ++ch) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            const float u = float(seed >> 40) / float(1u << 24);
            rgbx.push_back(std::ldexp(0.5f + u, int(seed >> 33) % 20 - 10));
        }
        rgbx.push_back(0.0f);
    }
    return rgbx;
}

bool sameBits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST(ProbeConvolutionOrder, EachTexelSumsItsRowLeftToRight) {
    for (int rays : {3, 17, 64, 256}) {
        const ProbeConvolution conv(passDirections(rays, 11), ProbeConvolution::Parts::IrradianceOnly);
        const std::vector<float> rgbx = radiance(std::size_t(rays), std::uint64_t(rays));
        std::vector<float> got(kIrradianceInteriorTexels * 3), var(kIrradianceInteriorTexels);
        conv.irradiance(rgbx.data(), got.data());
        conv.irradianceLumaVariance(rgbx.data(), var.data());
        int lengths = 0, last = -1;
        for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
            const ProbeConvolution::WeightRow row = conv.irradianceRow(t);
            ASSERT_GT(row.count, 0) << rays << " rays, texel " << t;
            lengths += row.count != last;
            last = row.count;
            float sum[3] = {0.0f, 0.0f, 0.0f}, e = 0.0f;
            for (int k = 0; k < row.count; ++k) {
                const float* L = &rgbx[4 * std::size_t(row.ray[k])];
                for (int ch = 0; ch < 3; ++ch)
                    sum[ch] += row.weight[k] * L[ch];
                e += row.weight[k] * pb::luminance(L);
            }
            const float mu = e / float(M_PI);
            float v = 0.0f;
            for (int k = 0; k < row.count; ++k) {
                const float w = row.weight[k];
                const float dy = pb::luminance(&rgbx[4 * std::size_t(row.ray[k])]) - mu;
                v += w * w * dy * dy;
            }
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_TRUE(sameBits(got[3 * std::size_t(t) + std::size_t(ch)], sum[ch]))
                    << rays << " rays, texel " << t << " channel " << ch << ": "
                    << got[3 * std::size_t(t) + std::size_t(ch)] << " vs " << sum[ch];
            EXPECT_TRUE(sameBits(var[std::size_t(t)], v))
                << rays << " rays, texel " << t << ": " << var[std::size_t(t)] << " vs " << v;
        }
        // Rows of unequal lengths side by side: what an interleaving could get wrong.
        if (rays >= 64) {
            EXPECT_GT(lengths, 8) << rays << " rays";
        }
    }
}
