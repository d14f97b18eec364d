// The cost model's replay of the SH technique (gi.technique=sh_l1|sh_l2, costmodel/
// ShFetchStream.h) on a baked scene and its own view, against DDGI's replay of the same set:
// the same pixels are evaluated; each lookup asks for 8 texels per coefficient texture (one
// trilinear 3D fetch each: 3 for L1, 7 for L2) plus the mask's 1 in weight / validity_mask;
// the footprints come from the 3D textures' layout; and far fewer bytes miss the cache.
#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "costmodel/ShFetchStream.h"
#include "costmodel/TextureMemory.h"
#include "raytrace/StaticTriangles.h"
#include "probes/bake/Baker.h"
#include "probes/placement/AutoVolume.h"
#include "scene/SceneLoader.h"
#include "views/WorstCaseView.h"

#include <cstdio>
#include <gtest/gtest.h>
#include <set>

using namespace pb;
using namespace pb::costmodel;

namespace {

struct Baked {
    scene::Scene scene;
    probes::ProbeSet set;
};

const Baked& baked() {
    static const Baked b = [] {
        Baked x{scene::makeBuiltinScene("rooms"), {}};
        probes::BakeRequest r;
        r.volumes.push_back(
            probes::fitAutoVolume(raytrace::staticBakeBounds(x.scene), 0.0f, 800).volume);
        r.scenarios = probes::resolveScenarios({"day"}, {}, x.scene);
        r.settings.raysPerProbe = 16;
        r.settings.bounces = 1;
        x.set = probes::bakeProbes(x.scene, r);
        return x;
    }();
    return b;
}

CostReport run(const std::string& technique, const std::string& leak) {
    const Baked& b = baked();
    CostModelOptions o;
    o.width = 160;
    o.height = 90;
    o.caches = {cachePresetFor("handheld")};
    o.profile.applyOverride("gi.technique=" + technique);
    if (technique != "ddgi") o.profile.applyOverride("gi.sh_leak=" + leak);
    return runCostModel(views::CoverageTester(b.scene, b.set), b.scene.views.front(), o);
}

const CacheResult& profileResult(const CostReport& r) {
    for (const CacheResult& res : r.results)
        if (res.variant == r.profileVariant) return res;
    throw std::runtime_error("no result for the profile's variant " + r.profileVariant);
}

} // namespace

TEST(CostModelSh, EachLookupReadsEightTexelsPerCoefficientTexturePlusTheMask) {
    ASSERT_TRUE(baked().set.hasSh());
    const CostReport ddgi = run("ddgi", "");
    ASSERT_EQ(ddgi.counters.volumes.size(), 1u);
    const VolumeCounters& dv = ddgi.counters.volumes[0];
    ASSERT_GT(dv.evaluated, 5000u);
    for (const char* technique : {"sh_l1", "sh_l2"})
        for (const char* leak : {"none", "weight", "validity_mask"}) {
            SCOPED_TRACE(std::string(technique) + " " + leak);
            const CostReport r = run(technique, leak);
            ASSERT_EQ(r.counters.volumes.size(), 1u);
            const VolumeCounters& v = r.counters.volumes[0];
            const int textures = shCoefficientTextures(r.profile.gi.technique);
            ASSERT_EQ(textures, std::string(technique) == "sh_l1" ? 3 : 7);
            // The same influence test and edge fade as DDGI's: the same pixels.
            EXPECT_EQ(v.evaluated, dv.evaluated);
            EXPECT_EQ(v.fadedOut, dv.fadedOut);
            EXPECT_EQ(v.stateFetches + v.visibilityFetches + v.irradianceFetches, 0u);
            const std::uint64_t looked = v.evaluated - v.fadedOut;
            const bool mask = std::string(leak) != "none";
            EXPECT_EQ(v.shMaskFetches, mask ? looked : 0u);
            // A cell whose 8 corners are all invalid stops after the mask (none reads anyway).
            EXPECT_EQ(v.shCoefficientFetches % std::uint64_t(textures), 0u);
            const std::uint64_t read = v.shCoefficientFetches / std::uint64_t(textures);
            EXPECT_LE(read, looked);
            EXPECT_GE(read, looked * 99 / 100);
            if (!mask) {
                EXPECT_EQ(read, looked);
            }
            // The formula: 8 texels per coefficient texture + 1 for the mask.
            EXPECT_EQ(v.probeTexels, 8 * std::uint64_t(textures) * read + v.shMaskFetches);
            EXPECT_EQ(shTexelsPerLookup(r.profile), 8 * textures + (mask ? 1 : 0));
            EXPECT_EQ(r.counters.maxFetchesPerLookup, 2 + textures + (mask ? 1 : 0));
            // Footprints from the 3D layout: at most 8 distinct 8-byte texels per fetch (fewer
            // where CLAMP_TO_EDGE folds them), 1 byte per mask fetch; and most are all 8.
            EXPECT_LE(v.probeFootprintBytes, 64 * v.shCoefficientFetches + v.shMaskFetches);
            EXPECT_GT(v.probeFootprintBytes, 48 * v.shCoefficientFetches);
            // Far fewer bytes than DDGI's: footprint and cache misses per GI pixel.
            const double px = double(r.counters.giPixels);
            const double missed = profileResult(r).probeBytesMissedPerPixel(px);
            const double ddgiMissed = profileResult(ddgi).probeBytesMissedPerPixel(px);
            std::printf("[ cost model sh ] %s/%s: %.2f probe texels per lookup, footprint %.1f "
                        "B/px (ddgi %.1f), hit rate %.4f (ddgi %.4f), bytes missed %.2f B/px "
                        "(ddgi %.2f)\n",
                        technique, leak, double(v.probeTexels) / double(looked),
                        double(v.probeFootprintBytes) / px, double(dv.probeFootprintBytes) / px,
                        profileResult(r).probeHitRate(), profileResult(ddgi).probeHitRate(), missed,
                        ddgiMissed);
            // L1 asks for 3 x 64 B per lookup where DDGI asks for 8 x 64 B, from textures of one
            // texel per probe: less than half the misses. L2 asks for 7 x 64 B: a smaller
            // footprint, but its misses are not always below DDGI's (on the gate's sparse rooms
            // file, whose DDGI tiles are packed, they are higher: studies/results
            // 2026-11-25-sh-technique-2.md), so only the footprint is held.
            if (textures == 3) {
                EXPECT_LT(v.probeFootprintBytes, dv.probeFootprintBytes / 2);
                EXPECT_LT(missed, 0.5 * ddgiMissed);
            } else {
                EXPECT_LT(v.probeFootprintBytes, dv.probeFootprintBytes);
            }
            EXPECT_EQ(r.counters.gpuProbeBytes,
                      std::uint64_t(baked().set.volumes[0].probeCount()) *
                          probes::shGpuBytesPerProbe(textures == 3 ? 4 : 9));
        }
}

// The 3D textures' tiled layout: 4 KiB bricks in 3D Morton order, so an aligned 2x2x2
// footprint of 8-byte texels is one 64-byte line, and every texel has its own address inside
// the texture.
TEST(CostModelSh, VolumeTexturesAreTiledInBricks) {
    const TextureMemory m(kTextureAlignment, 20, 12, 9, 1, 8, MemoryLayout::Tiled, true);
    std::set<std::uint64_t> seen;
    for (int l = 0; l < 9; ++l)
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) {
                const std::uint64_t a = m.address(x, y, l);
                EXPECT_GE(a, m.base());
                EXPECT_LT(a + 8, m.base() + m.bytes() + 1);
                EXPECT_TRUE(seen.insert(a).second) << x << " " << y << " " << l;
            }
    for (int l = 0; l + 1 < 9; l += 2)
        for (int y = 0; y + 1 < 12; y += 2)
            for (int x = 0; x + 1 < 20; x += 2) {
                std::set<std::uint64_t> lines;
                for (int c = 0; c < 8; ++c)
                    lines.insert(m.address(x + (c & 1), y + (c >> 1 & 1), l + (c >> 2)) / 64);
                EXPECT_EQ(lines.size(), 1u) << x << " " << y << " " << l;
            }
    // 2D textures keep one tile per layer: the same footprint spans two lines at least.
    const TextureMemory flat(kTextureAlignment, 20, 12, 9, 1, 8, MemoryLayout::Tiled);
    EXPECT_NE(flat.address(0, 0, 0) / 64, flat.address(0, 0, 1) / 64);
}
