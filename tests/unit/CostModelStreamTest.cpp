// The cost model's address stream: one pixel's fetches are the sampler's texels (checked
// against the GL texel formula of the README), ordered per variant (slice_first: the 4 probes
// of one layer before the other layer; split: every visibility fetch before any irradiance
// fetch), invalid probes read only their state, and the texel -> byte address maps.
#include "costmodel/FetchStream.h"
#include "costmodel/GiVariant.h"
#include "costmodel/PixelOrder.h"
#include "probes/Octahedral.h"
#include "probes/ProbeSampler.h"

#include "OpenProbeSets.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pb;
using namespace pb::costmodel;

namespace {

// A 4x3x5 grid over [0,4]x[0,2]x[0,4] with open visibility; probe `invalid` (or none) invalid.
probes::ProbeSet costModelStreamGridSet(int invalid = -1) {
    probes::ProbeSet set =
        test::openProbeSet({test::gridVolume("grid", {2, 1, 2}, {2, 1, 2}, {4, 3, 5})});
    if (invalid >= 0) set.states[0][size_t(invalid)].valid = false;
    return set;
}

const glm::vec3 kPos{1.3f, 0.8f, 2.9f}, kNormal{0.3f, 0.9f, -0.2f}, kView{-0.5f, 0.4f, 0.7f};

probes::SampleTrace traceAt(const probes::ProbeSet& set) {
    probes::ProbeSampler s(set, 0);
    probes::SampleTrace t;
    s.sampleVolume(0, kPos, kNormal, kView, {}, &t);
    return t;
}

glm::ivec2 glFootprint(glm::vec2 coord) {
    return {int(std::floor(coord.x - 0.5f)), int(std::floor(coord.y - 0.5f))};
}

} // namespace

TEST(CostModelStream, TraceTexelsAreTheGlFootprintOfTheReadmeFormulas) {
    const probes::ProbeSet set = costModelStreamGridSet();
    const probes::SampleTrace t = traceAt(set);
    ASSERT_TRUE(t.probesRead);
    // README "The sampler", axis-aligned volume: local = world - (centre - half).
    const glm::vec3 p = kPos - glm::vec3(2, 1, 2), n = glm::normalize(kNormal);
    const glm::vec3 v = glm::normalize(kView);
    const float minCell = 1.0f; // cells 4/3, 1, 1
    const glm::vec3 biased =
        p + (probes::kBiasNormalWeight * n + probes::kBiasViewWeight * v) *
                (probes::kBiasScale * minCell);
    const glm::vec3 cell{4.0f / 3.0f, 1.0f, 1.0f};
    const glm::ivec3 base = glm::ivec3(glm::floor((p + glm::vec3(2, 1, 2)) / cell));
    for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 q = base + glm::ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
        const probes::CornerFetch& c = t.corners[corner];
        ASSERT_TRUE(c.inGrid);
        EXPECT_EQ(c.probe, q);
        const glm::vec3 probePos = glm::vec3(-2, -1, -2) + glm::vec3(q) * cell;
        const glm::vec3 dir = glm::normalize(biased - probePos);
        EXPECT_EQ(glm::ivec2(c.visTexel),
                  glFootprint(probes::tileCoord(q, dir, probes::kVisibilityInterior)))
            << corner;
        EXPECT_EQ(glm::ivec2(c.irradianceTexel),
                  glFootprint(probes::tileCoord(q, n, probes::kIrradianceInterior)))
            << corner;
    }
}

TEST(CostModelStream, FusedXyzIssuesStateVisibilityIrradiancePerProbeInCornerOrder) {
    const probes::ProbeSet set = costModelStreamGridSet();
    const probes::SampleTrace t = traceAt(set);
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    std::vector<Fetch> f;
    appendProbeFetches(t, variantStructure({}), table.volumes[0], f);
    ASSERT_EQ(f.size(), 24u);
    for (int corner = 0; corner < 8; ++corner) {
        const probes::CornerFetch& c = t.corners[corner];
        const Fetch &st = f[size_t(3 * corner)], &vis = f[size_t(3 * corner + 1)],
                    &irr = f[size_t(3 * corner + 2)];
        EXPECT_EQ(st.kind, FetchKind::ProbeState);
        EXPECT_EQ(glm::ivec3(st.x, st.layer, st.y), c.probe); // texel (i, k) of layer j
        EXPECT_FALSE(st.bilinear);
        EXPECT_EQ(vis.kind, FetchKind::Visibility);
        EXPECT_EQ(glm::ivec2(vis.x, vis.y), c.visTexel);
        EXPECT_EQ(vis.layer, c.probe.y);
        EXPECT_TRUE(vis.bilinear);
        EXPECT_EQ(irr.kind, FetchKind::Irradiance);
        EXPECT_EQ(glm::ivec2(irr.x, irr.y), c.irradianceTexel);
        EXPECT_EQ(irr.layer, c.probe.y);
        EXPECT_EQ(st.slot, 2 + 3 * corner); // after the two GBuffer fetches
    }
}

TEST(CostModelStream, SliceFirstVisitsOneLayerBeforeTheOther) {
    const probes::ProbeSet set = costModelStreamGridSet();
    const probes::SampleTrace t = traceAt(set);
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    for (auto loops : {profile::GiLoops::Fused, profile::GiLoops::Split}) {
        std::vector<Fetch> f;
        appendProbeFetches(t, variantStructure({profile::GiProbeOrder::SliceFirst, loops}),
                           table.volumes[0], f);
        std::vector<int> layers; // per visibility fetch, in issue order
        for (const Fetch& x : f)
            if (x.kind == FetchKind::Visibility) layers.push_back(x.layer);
        ASSERT_EQ(layers.size(), 8u);
        for (int i = 0; i < 8; ++i)
            EXPECT_EQ(layers[size_t(i)], t.corners[0].probe.y + (i >= 4)) << i;
        // xyz alternates layers every two probes.
        std::vector<Fetch> g;
        appendProbeFetches(t, variantStructure({profile::GiProbeOrder::Xyz, loops}),
                           table.volumes[0], g);
        std::vector<int> xyz;
        for (const Fetch& x : g)
            if (x.kind == FetchKind::Visibility) xyz.push_back(x.layer - t.corners[0].probe.y);
        EXPECT_EQ(xyz, (std::vector<int>{0, 0, 1, 1, 0, 0, 1, 1}));
    }
}

TEST(CostModelStream, SplitIssuesEveryVisibilityFetchBeforeAnyIrradianceFetch) {
    const probes::ProbeSet set = costModelStreamGridSet();
    const probes::SampleTrace t = traceAt(set);
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    std::vector<Fetch> split, fused;
    appendProbeFetches(t, variantStructure({profile::GiProbeOrder::Xyz, profile::GiLoops::Split}),
                       table.volumes[0], split);
    appendProbeFetches(t, variantStructure({}), table.volumes[0], fused);
    ASSERT_EQ(split.size(), fused.size()); // the same fetches, another order
    size_t lastVis = 0, firstIrr = split.size();
    for (size_t i = 0; i < split.size(); ++i) {
        if (split[i].kind == FetchKind::Visibility) lastVis = i;
        if (split[i].kind == FetchKind::Irradiance) firstIrr = std::min(firstIrr, i);
    }
    EXPECT_LT(lastVis, firstIrr);
    for (size_t i = 1; i < split.size(); ++i)
        EXPECT_GT(split[i].slot, split[i - 1].slot); // one instruction each, in program order
}

TEST(CostModelStream, AnInvalidProbeReadsOnlyItsState) {
    const probes::ProbeSet clean = costModelStreamGridSet();
    const probes::CornerFetch c5 = traceAt(clean).corners[5];
    const probes::ProbeSet bad = costModelStreamGridSet(clean.volumes[0].probeIndex(c5.probe));
    const probes::SampleTrace t = traceAt(bad);
    EXPECT_FALSE(t.corners[5].valid);
    const TextureTable table = makeTextureTable(64, 64, bad, {0}, MemoryLayout::Linear);
    std::vector<Fetch> f;
    appendProbeFetches(t, variantStructure({}), table.volumes[0], f);
    EXPECT_EQ(f.size(), 22u);
    int states = 0;
    for (const Fetch& x : f)
        if (glm::ivec3(x.x, x.layer, x.y) == c5.probe && x.kind != FetchKind::ProbeState)
            ADD_FAILURE() << "invalid probe fetched " << fetchKindName(x.kind);
        else if (x.kind == FetchKind::ProbeState)
            ++states;
    EXPECT_EQ(states, 8);
}

TEST(CostModelStream, TexelAddressesPerLayoutAndFormat) {
    // Linear: rows back to back, layers after each other.
    const TextureMemory lin(65536, 10, 6, 3, 1, 8, MemoryLayout::Linear);
    EXPECT_EQ(lin.address(0, 0, 0), 65536u);
    EXPECT_EQ(lin.address(3, 2, 1), 65536u + ((1 * 6 + 2) * 10 + 3) * 8u);
    // Tiled, 8 B texels: 4 KiB tiles of 32 x 16 in Morton order (x in the lowest bit).
    const TextureMemory til(0, 64, 32, 1, 1, 8, MemoryLayout::Tiled);
    EXPECT_EQ(til.address(1, 0, 0), 8u);
    EXPECT_EQ(til.address(0, 1, 0), 16u);
    EXPECT_EQ(til.address(1, 1, 0), 24u);
    EXPECT_EQ(til.address(2, 0, 0), 32u);
    EXPECT_EQ(til.address(32, 0, 0), 4096u); // the next tile to the right
    EXPECT_EQ(til.address(0, 16, 0), 8192u); // the next tile row (2 tiles per row)
    // BC6H: the 16 texels of a 4x4 block share one 16 B block.
    const TextureMemory bc(0, 16, 16, 1, 4, 16, MemoryLayout::Linear);
    EXPECT_EQ(bc.address(0, 0, 0), bc.address(3, 3, 0));
    EXPECT_EQ(bc.address(4, 0, 0), 16u);
    EXPECT_EQ(bc.address(0, 4, 0), 64u);
    EXPECT_EQ(bc.bytes(), 256u);
}

TEST(CostModelStream, FootprintBytesCountDistinctTexelsOrBlocks) {
    const probes::ProbeSet set = costModelStreamGridSet();
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    const Fetch vis{FetchKind::Visibility, table.volumes[0].visibility, 5, 5, 0, true, 3};
    EXPECT_EQ(footprintBytes(vis, table), 4u * 4u); // RG16F
    const Fetch st{FetchKind::ProbeState, table.volumes[0].state, 1, 1, 0, false, 2};
    EXPECT_EQ(footprintBytes(st, table), 16u);
    probes::ProbeSet bcSet = costModelStreamGridSet();
    bcSet.settings.format = probes::StorageFormat::Bc6h;
    const TextureTable bc = makeTextureTable(64, 64, bcSet, {0}, MemoryLayout::Linear);
    const Fetch inside{FetchKind::Irradiance, bc.volumes[0].irradiance, 1, 1, 0, true, 4};
    const Fetch across{FetchKind::Irradiance, bc.volumes[0].irradiance, 3, 3, 0, true, 4};
    EXPECT_EQ(footprintBytes(inside, bc), 16u);      // one block
    EXPECT_EQ(footprintBytes(across, bc), 4u * 16u); // four blocks
}

TEST(CostModelStream, PixelOrderIsTilesOfQuads) {
    const std::vector<glm::ivec2> o = gpuPixelOrder(10, 5, 4);
    ASSERT_EQ(o.size(), 50u);
    const std::vector<glm::ivec2> first = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0},
                                           {3, 0}, {2, 1}, {3, 1}, {0, 2}, {1, 2}};
    for (size_t i = 0; i < first.size(); ++i)
        EXPECT_EQ(o[i], first[i]) << i;
    EXPECT_EQ(o[16], glm::ivec2(4, 0)); // the second tile after the 16 pixels of the first
    std::vector<int> seen(50, 0);
    for (const glm::ivec2& p : o)
        ++seen[size_t(p.y * 10 + p.x)];
    for (int s : seen)
        EXPECT_EQ(s, 1);
}
