// The irradiance storage scale (probes/StorageScale.h): chosen as documented, applied before
// quantisation and divided out after it (the CPU sees true values), carried through the probe
// file, and 1 - the stored bytes unchanged - for a bake of ordinary brightness.
#include "probes/StorageScale.h"
#include "ProbeTestScenes.h"
#include "probes/bake/Baker.h"
#include "probes/store/ProbeFile.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::probes;

namespace {

// `sparse`: a taller volume whose upper probe layers see no surface cell, stored sparse.
ProbeSet roomBake(StorageFormat format, float lightScale, bool sparse = false) {
    const pb::scene::Scene s = pb::test::sunlitFloor(lightScale);
    BakeRequest r;
    ProbeVolume v;
    v.name = "v";
    v.center = {0, 1, 0};
    v.halfExtents = {2, 0.9f, 2};
    v.counts = {3, 2, 3};
    if (sparse) {
        v.center = {0, 1.5f, 0};
        v.halfExtents = {2, 1.5f, 2};
        v.counts = {3, 4, 3};
        r.sparse = true;
    }
    r.volumes = {v};
    r.scenarios = resolveScenarios({"day", "night"}, {}, s);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 1;
    r.settings.format = format;
    // The texels under test are the storage's: pinned to the rays alone, so that the BC6H
    // worst-texel tolerance below keeps describing the same probe pattern whatever the default
    // light sampling becomes (lit-surface samples change which texels are dim in a block).
    r.settings.litSamples = 0;
    return bakeProbes(s, r);
}

// The texels of `set` divided by those of `ref`, over RGB texels where ref is not tiny.
double worstRatioError(const ProbeTexture& t, const ProbeTexture& ref, double lightScale) {
    double worst = 0.0;
    for (std::size_t i = 0; i < t.texels.size(); ++i) {
        if (i % 4 == 3 || ref.texels[i] < 1e-2f) continue;
        worst = std::max(worst, std::abs(t.texels[i] / (ref.texels[i] * lightScale) - 1.0));
    }
    return worst;
}

} // namespace

TEST(StorageScale, OneInsideTheComfortableRange) {
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Bc6h}) {
        EXPECT_EQ(chooseStorageScale(0.0f, f), 1.0f);
        EXPECT_EQ(chooseStorageScale(kScaleLow, f), 1.0f);
        EXPECT_EQ(chooseStorageScale(1.0f, f), 1.0f);
        EXPECT_EQ(chooseStorageScale(kScaleHigh, f), 1.0f);
    }
    // fp32 has the range: never scaled.
    EXPECT_EQ(chooseStorageScale(1e9f, StorageFormat::Rgba32f), 1.0f);
    EXPECT_EQ(chooseStorageScale(1e-9f, StorageFormat::Rgba32f), 1.0f);
}

TEST(StorageScale, OutsideItTheMaximumLandsInTheTopOctaveBelowHigh) {
    for (float m : {1e-9f, 1e-6f, 3e-5f, 0.01f, 20000.0f, 65504.0f, 1e6f, 3e9f}) {
        const float s = chooseStorageScale(m, StorageFormat::Rgba16f);
        EXPECT_TRUE(isValidStorageScale(s)) << m;
        EXPECT_LE(m * s, kScaleHigh) << m;
        EXPECT_GT(m * s, kScaleHigh / 2) << m;
    }
    // Limited to 2^+-64 (a file may not hold more), even for absurd maxima.
    EXPECT_EQ(chooseStorageScale(1e-30f, StorageFormat::Bc6h), std::ldexp(1.0f, 64));
    EXPECT_EQ(chooseStorageScale(3e38f, StorageFormat::Bc6h), std::ldexp(1.0f, -64));
}

TEST(StorageScale, ValidScalesArePowersOfTwoInRange) {
    EXPECT_TRUE(isValidStorageScale(1.0f));
    EXPECT_TRUE(isValidStorageScale(std::ldexp(1.0f, 64)));
    EXPECT_TRUE(isValidStorageScale(std::ldexp(1.0f, -64)));
    EXPECT_FALSE(isValidStorageScale(std::ldexp(1.0f, 65)));
    EXPECT_FALSE(isValidStorageScale(std::ldexp(1.0f, -65)));
    for (float bad :
         {0.0f, -0.0f, -1.0f, 3.0f, 0.75f, std::numeric_limits<float>::quiet_NaN(),
          std::numeric_limits<float>::infinity(), std::numeric_limits<float>::denorm_min()})
        EXPECT_FALSE(isValidStorageScale(bad)) << bad;
}

TEST(StorageScale, QuantiseStoresScaledAndDecodesTrueValues) {
    ProbeTexture t = ProbeTexture::make(irradianceShape({1, 1, 1}));
    for (std::size_t i = 0; i < t.texels.size(); ++i)
        t.texels[i] = i % 4 == 3 ? 1.0f : 1e6f; // past fp16's 65504
    t.storageScale = chooseStorageScale(maxIrradiance({t}), StorageFormat::Rgba16f);
    ASSERT_LT(t.storageScale, 1.0f);
    quantise(t, StorageFormat::Rgba16f);
    for (std::size_t i = 0; i < t.texels.size(); ++i)
        EXPECT_NEAR(t.texels[i], i % 4 == 3 ? 1.0f : 1e6f, 1e6f * 1e-3f) << i; // not 65504
}

// A scene lit 1e6 and 1e-6 times as brightly bakes to the same irradiance times the factor,
// in rgba16f and bc6h alike (before: clamped at 65504 / stored as fp16 denormals).
TEST(StorageScale, ExtremeBakesKeepTheirValuesAndRoundTripThroughTheFile) {
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Bc6h}) {
        const ProbeSet ref = roomBake(f, 1.0f);
        for (float k : {1e6f, 1e-6f}) {
            const ProbeSet set = roomBake(f, k);
            const float s = set.irradiance[0][0].storageScale;
            EXPECT_NE(s, 1.0f) << formatName(f) << " x" << k;
            EXPECT_EQ(s, chooseStorageScale(maxIrradiance(set.irradiance[0]), f));
            const double tolerance = f == StorageFormat::Bc6h ? 0.08 : 0.01;
            EXPECT_LT(worstRatioError(set.irradiance[0][0], ref.irradiance[0][0], k), tolerance)
                << formatName(f) << " x" << k;
            const ProbeSet back = parseProbeSet(serializeProbeSet(set), "probes.pbp");
            for (std::size_t sc = 0; sc < set.scenarios.size(); ++sc) {
                EXPECT_EQ(back.irradiance[sc][0].storageScale, set.irradiance[sc][0].storageScale);
                EXPECT_EQ(back.irradiance[sc][0].texels, set.irradiance[sc][0].texels);
                EXPECT_EQ(back.irradiance[sc][0].stored, set.irradiance[sc][0].stored);
            }
        }
    }
}

// Both records of the file at once: a sparse set (packed tiles) of a scaled scenario keeps its
// scale and true values through the file, and the packed tiles are what is scaled.
TEST(StorageScale, SparseScaledBakesRoundTripThroughTheFile) {
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Bc6h}) {
        const ProbeSet set = roomBake(f, 1e6f, true);
        ASSERT_LT(set.storedCount(), set.probeCount()) << formatName(f);
        ASSERT_GT(set.storedCount(), 0u) << formatName(f);
        EXPECT_NE(set.irradiance[0][0].storageScale, 1.0f) << formatName(f);
        const ProbeSet back = parseProbeSet(serializeProbeSet(set), "sparse.pbp");
        for (std::size_t sc = 0; sc < set.scenarios.size(); ++sc) {
            EXPECT_EQ(back.irradiance[sc][0].storageScale, set.irradiance[sc][0].storageScale);
            EXPECT_EQ(back.irradiance[sc][0].texels, set.irradiance[sc][0].texels);
        }
        const ProbeSet ref = roomBake(f, 1.0f, true);
        const double tolerance = f == StorageFormat::Bc6h ? 0.08 : 0.01;
        EXPECT_LT(worstRatioError(back.irradiance[0][0], ref.irradiance[0][0], 1e6), tolerance)
            << formatName(f);
    }
}

// Ordinary brightness (the day and night presets): scale 1, which quantise() skips, so the
// stored bytes are those of a bake without storage scales.
TEST(StorageScale, OrdinaryBakesAreStoredUnscaled) {
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Rgba32f, StorageFormat::Bc6h}) {
        const ProbeSet set = roomBake(f, 1.0f);
        ASSERT_EQ(set.scenarios.size(), 2u);
        for (std::size_t sc = 0; sc < 2; ++sc)
            EXPECT_EQ(set.irradiance[sc][0].storageScale, 1.0f)
                << formatName(f) << " " << set.scenarios[sc].name;
    }
}
