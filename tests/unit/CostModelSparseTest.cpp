// The cost model on a sparse probe set (renderer/probes/README.md "Sparse storage"): the
// irradiance and visibility textures have the packed extent GpuProbes uploads, every probe
// fetch lands in the packed tile of a stored corner of its lookup (the tile the shader's
// ddgiTile finds from the state's w), absent probes read only their state (no extra fetch for
// the indirection), and on a baked scene a sparse set issues exactly the dense set's fetches -
// no surface reads a dropped probe - from textures of the packed size.
#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "costmodel/FetchStream.h"
#include "profile/GiVolumeLod.h"
#include "probes/placement/AutoVolume.h"
#include "probes/bake/Baker.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeSampler.h"
#include "raytrace/RayScene.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "raytrace/StaticTriangles.h"
#include "scene/SceneLoader.h"
#include "views/WorstCaseView.h"

#include "OpenProbeSets.h"

#include <gtest/gtest.h>

#include <random>

using namespace pb;
using namespace pb::costmodel;

namespace {

// A 5x3x4 grid over [0,5]x[0,2]x[0,4] with open visibility; the probes `absent` picks are not
// stored (and so invalid, as SparseStorage leaves them), or with `onlyInvalid` only invalid.
// They lie inside geometry (back-face ratio 1), so no stand-in replaces them
// (probes/AbsentProbeFill.h) unless `outside`: then absent ones are read as stand-ins.
template <typename Pick>
probes::ProbeSet gridSet(Pick absent, bool onlyInvalid = false, bool outside = false) {
    const probes::ProbeVolume v = test::gridVolume("grid", {2.5f, 1, 2}, {2.5f, 1, 2}, {5, 3, 4});
    probes::ProbeSet set = test::openProbeSet({v});
    for (int i = 0; i < v.probeCount(); ++i)
        if (absent(v.probeCoords(i))) {
            set.states[0][size_t(i)].valid = false;
            set.states[0][size_t(i)].stored = onlyInvalid;
            set.states[0][size_t(i)].backfaceRatio = outside ? 0.0f : 1.0f;
        }
    return set;
}

// A third of the probes absent, spread over every layer.
bool everyThird(const glm::ivec3& q) {
    return (q.x + 2 * q.y + 3 * q.z) % 3 == 0;
}

struct Lookup {
    probes::SampleTrace trace;
    std::vector<Fetch> fetches;
};

// Lookups at points all over the box, in both loop structures' union of fetch kinds (fused).
std::vector<Lookup> lookups(const probes::ProbeSet& set, const TextureTable& table) {
    const probes::ProbeSampler sampler(set, 0);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Lookup> out;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 p(5.0f * u(rng), 2.0f * u(rng), 4.0f * u(rng));
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) - 0.5f + 1e-3f);
        Lookup l;
        sampler.sampleVolume(0, p, n, n, {}, &l.trace);
        appendProbeFetches(l.trace, variantStructure({}), table.volumes[0], l.fetches);
        out.push_back(std::move(l));
    }
    return out;
}

} // namespace

TEST(CostModelSparse, ProbeTexturesHaveThePackedExtent) {
    const probes::ProbeSet set = gridSet(everyThird);
    const probes::ProbeVolume& v = set.volumes[0];
    const std::size_t stored = probes::storedCount(set.states[0]);
    ASSERT_LT(stored, std::size_t(v.probeCount()));
    const glm::ivec3 packed = probes::packedCounts(stored, v.counts);
    ASSERT_NE(packed, v.counts);
    const TextureTable t = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    const TextureTable::Volume& tex = t.volumes[0];
    EXPECT_TRUE(tex.tiles.sparse);
    EXPECT_EQ(tex.tiles.packedCounts, packed);
    // Linear rows: the texture's bytes are exactly the packed data GpuProbes uploads.
    EXPECT_EQ(t.textures[size_t(tex.irradiance)].bytes(),
              probes::storedBytes(probes::irradianceShape(packed), set.format()));
    EXPECT_EQ(t.textures[size_t(tex.visibility)].bytes(),
              probes::storedBytes(probes::visibilityShape(packed), set.format()));
    EXPECT_EQ(t.textures[size_t(tex.state)].bytes(),
              std::uint64_t(v.probeCount()) * probes::kStateBytesPerProbe); // the indirection
    // The memory counter agrees: packed tiles + the state texture.
    EXPECT_EQ(profile::gpuVolumeBytes(set, 0), t.textures[size_t(tex.irradiance)].bytes() +
                                                  t.textures[size_t(tex.visibility)].bytes() +
                                                  t.textures[size_t(tex.state)].bytes());
}

TEST(CostModelSparse, EveryProbeFetchLandsInItsStoredCornersPackedTile) {
    const probes::ProbeSet set = gridSet(everyThird);
    const probes::ProbeVolume& v = set.volumes[0];
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    const TextureTable::Volume& tex = table.volumes[0];
    const std::vector<int> slots = probes::packedSlots(set.states[0]);
    const int stored = int(probes::storedCount(set.states[0]));
    const glm::ivec3 pc = tex.tiles.packedCounts;
    int tileFetches = 0;
    for (const Lookup& l : lookups(set, table)) {
        // Per corner as the shader visits it: the state, then (stored and valid only) the tile.
        int expected = 0, states = 0;
        for (const probes::CornerFetch& c : l.trace.corners)
            if (c.inGrid) expected += set.states[0][size_t(v.probeIndex(c.probe))].stored ? 2 : 0;
        for (const Fetch& f : l.fetches) {
            if (f.kind == FetchKind::ProbeState) {
                ++states;
                EXPECT_EQ(f.texture, tex.state);
                continue;
            }
            const bool vis = f.kind == FetchKind::Visibility;
            const int size = vis ? probes::kVisibilityTile : probes::kIrradianceTile;
            EXPECT_EQ(f.texture, vis ? tex.visibility : tex.irradiance);
            // The packed slot whose tile holds the whole 2x2 footprint: a stored tile.
            const glm::ivec3 tile(f.x / size, f.y / size, f.layer);
            ASSERT_EQ((f.x + 1) / size, tile.x);
            ASSERT_EQ((f.y + 1) / size, tile.y);
            ASSERT_TRUE(tile.x < pc.x && tile.y < pc.z && tile.z < pc.y);
            const int slot = (tile.z * pc.z + tile.y) * pc.x + tile.x;
            ASSERT_LT(slot, stored) << "a fetch outside the stored tiles";
            EXPECT_EQ(probes::packedTile(slot, pc), tile);
            // ... and it is the tile of a stored corner of this lookup, at the same place in
            // the tile as the dense layout's texel.
            bool owner = false;
            for (const probes::CornerFetch& c : l.trace.corners) {
                if (!c.inGrid || slots[size_t(v.probeIndex(c.probe))] != slot) continue;
                const glm::ivec2 dense = vis ? c.visTexel : c.irradianceTexel;
                owner = owner || dense - glm::ivec2(c.probe.x, c.probe.z) * size ==
                                     glm::ivec2(f.x, f.y) - glm::ivec2(tile) * size;
            }
            EXPECT_TRUE(owner) << "fetch at tile " << tile.x << "," << tile.y << "," << tile.z;
            ++tileFetches;
            --expected;
        }
        if (l.trace.probesRead) {
            EXPECT_EQ(expected, 0) << "tile fetches per stored corner";
        }
        EXPECT_EQ(states, l.trace.probesRead ? 8 : 0); // no extra fetch for the indirection
    }
    EXPECT_GT(tileFetches, 1000);
}

// Issue 18: an absent probe outside geometry is read as its nearest stored probe. The cost
// model replays that: its state, then its stand-in's packed tile, as for a stored corner.
TEST(CostModelSparse, AStandInsFetchesLandInItsSourcesTile) {
    const probes::ProbeSet set = gridSet(everyThird, false, true);
    const probes::ProbeVolume& v = set.volumes[0];
    const TextureTable table = makeTextureTable(64, 64, set, {0}, MemoryLayout::Linear);
    const TextureTable::Volume& tex = table.volumes[0];
    const std::vector<int> slots = probes::packedSlots(set.states[0]);
    const std::vector<int> source =
        probes::fillSources(v, set.states[0], set.settings.backfaceThreshold);
    ASSERT_EQ(source.size(), set.states[0].size());
    int standInFetches = 0;
    for (const Lookup& l : lookups(set, table)) {
        int expected = 0;
        for (const probes::CornerFetch& c : l.trace.corners)
            expected += c.inGrid && c.valid ? 2 : 0; // every in-grid corner reads a tile now
        int tiles = 0;
        for (const Fetch& f : l.fetches) {
            if (f.kind == FetchKind::ProbeState) continue;
            ++tiles;
            const int size = f.kind == FetchKind::Visibility ? probes::kVisibilityTile
                                                             : probes::kIrradianceTile;
            const glm::ivec3 tile(f.x / size, f.y / size, f.layer);
            // The tile belongs to a corner's own stored tile or its stand-in's.
            bool owner = false;
            for (const probes::CornerFetch& c : l.trace.corners) {
                if (!c.inGrid) continue;
                const int i = v.probeIndex(c.probe), s = source[size_t(i)];
                owner = owner || (s >= 0 && slots[size_t(s)] >= 0 &&
                                  probes::packedTile(slots[size_t(s)], tex.tiles.packedCounts) ==
                                      tile);
                standInFetches += s != i && tex.tiles.tileOf(c.probe) == tile ? 1 : 0;
            }
            EXPECT_TRUE(owner) << "fetch at tile " << tile.x << "," << tile.y << "," << tile.z;
        }
        if (l.trace.probesRead) {
            EXPECT_EQ(tiles, expected);
        }
    }
    EXPECT_GT(standInFetches, 100);
}

TEST(CostModelSparse, AbsentProbesCostWhatInvalidOnesCost) {
    // The same probes absent (packed layout) or only invalid (dense layout): the same fetches
    // by kind, instruction and state texel; only the tiles' addresses move.
    const probes::ProbeSet sparse = gridSet(everyThird), invalid = gridSet(everyThird, true);
    const TextureTable ts = makeTextureTable(64, 64, sparse, {0}, MemoryLayout::Tiled);
    const TextureTable ti = makeTextureTable(64, 64, invalid, {0}, MemoryLayout::Tiled);
    ASSERT_TRUE(ts.volumes[0].tiles.sparse);
    ASSERT_FALSE(ti.volumes[0].tiles.sparse);
    const std::vector<Lookup> a = lookups(sparse, ts), b = lookups(invalid, ti);
    ASSERT_EQ(a.size(), b.size());
    int moved = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].fetches.size(), b[i].fetches.size()) << i;
        for (size_t k = 0; k < a[i].fetches.size(); ++k) {
            const Fetch &x = a[i].fetches[k], &y = b[i].fetches[k];
            EXPECT_EQ(x.kind, y.kind);
            EXPECT_EQ(x.slot, y.slot);
            EXPECT_EQ(footprintBytes(x, ts), footprintBytes(y, ti));
            if (x.kind == FetchKind::ProbeState)
                EXPECT_TRUE(x.x == y.x && x.y == y.y && x.layer == y.layer);
            else
                moved += x.x != y.x || x.y != y.y || x.layer != y.layer;
        }
    }
    EXPECT_GT(moved, 0) << "no tile moved: the packed layout was not used";
}

TEST(CostModelSparse, ABakedSparseSetReadsTheDenseSetsTexelsFromPackedTextures) {
    const scene::Scene s = scene::makeBuiltinScene("courtyard");
    probes::BakeRequest r;
    r.volumes.push_back(probes::fitAutoVolume(raytrace::staticBakeBounds(s), 0.0f, 800).volume);
    r.scenarios = probes::resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 16;
    r.settings.bounces = 1;
    const probes::ProbeSet dense = probes::bakeProbes(s, r);
    probes::ProbeSet sparse = dense;
    probes::applySparseStorage(sparse, raytrace::staticBakeTriangles(s));
    ASSERT_LT(sparse.storedCount(), dense.probeCount() - dense.invalidCount());

    CostModelOptions o;
    o.width = 96;
    o.height = 54;
    o.caches = {cachePresetFor("handheld")};
    const scene::View& view = s.views.front();
    const CostReport d = runCostModel(views::CoverageTester(s, dense), view, o);
    const CostReport p = runCostModel(views::CoverageTester(s, sparse), view, o);
    ASSERT_EQ(d.counters.volumes.size(), 1u);
    ASSERT_EQ(p.counters.volumes.size(), 1u);
    const VolumeCounters &dv = d.counters.volumes[0], &pv = p.counters.volumes[0];
    ASSERT_GT(dv.evaluated, 1000u);
    // No surface pixel reads a dropped probe (SparseStorage.h), and the indirection rides on
    // the state fetch: every count is the dense one.
    EXPECT_EQ(pv.evaluated, dv.evaluated);
    EXPECT_EQ(pv.stateFetches, dv.stateFetches);
    EXPECT_EQ(pv.visibilityFetches, dv.visibilityFetches);
    EXPECT_EQ(pv.irradianceFetches, dv.irradianceFetches);
    EXPECT_EQ(pv.probeFootprintBytes, dv.probeFootprintBytes);
    // ... from textures of the packed size,
    EXPECT_EQ(p.counters.gpuProbeBytes, profile::gpuVolumeBytes(sparse, 0));
    EXPECT_LT(p.counters.gpuProbeBytes, d.counters.gpuProbeBytes);
    // ... and only from stored tiles: every pixel's tile fetches, addressed as replayed, lie
    // inside the packed textures' first storedCount tiles.
    const TextureTable table =
        makeTextureTable(o.width, o.height, sparse, {0}, MemoryLayout::Linear);
    const TextureTable::Volume& tex = table.volumes[0];
    const glm::ivec3 pc = tex.tiles.packedCounts;
    ASSERT_TRUE(tex.tiles.sparse);
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x)
            pixels.push_back({x, y});
    const views::CoverageTester tester(s, sparse);
    const probes::ProbeSampler sampler(sparse, 0);
    std::size_t tileFetches = 0;
    for (const views::SurfacePoint& sp : tester.surfacePoints(view, o.width, o.height, pixels)) {
        if (!sp.hit || !sampler.influencesPoint(0, sp.position)) continue;
        probes::SampleTrace trace;
        sampler.sampleVolume(0, sp.position, sp.normal, view.position - sp.position, {}, &trace);
        std::vector<Fetch> fetches;
        appendProbeFetches(trace, variantStructure({}), tex, fetches);
        for (const Fetch& f : fetches) {
            if (f.kind == FetchKind::ProbeState) continue;
            const int size =
                f.kind == FetchKind::Visibility ? probes::kVisibilityTile : probes::kIrradianceTile;
            const int slot = (f.layer * pc.z + f.y / size) * pc.x + f.x / size;
            ASSERT_LT(std::size_t(slot), sparse.storedCount());
            ++tileFetches;
        }
    }
    EXPECT_EQ(tileFetches, pv.visibilityFetches + pv.irradianceFetches);
}
