// Sparse probe storage (issue 9): the packed tile layout and its inverse, which probes the
// surface test keeps, the probe file round trip of a sparse set, and the guarantee that lets
// sparse storage drop probes at all: no surface point's irradiance changes.
#include "probes/store/SparseStorage.h"
#include "OlderProbeFile.h"
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "fuzz/FuzzInputs.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeCounts.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/Baker.h"
#include "raytrace/RayScene.h"
#include "probes/bake/SceneMatch.h"
#include "probes/placement/AutoVolume.h"
#include "core/Hash.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/SparseLayout.h"
#include "scene/SceneLoader.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>
#include <random>

using namespace pb::probes;

namespace {

ProbeTexture randomTexture(const TextureShape& shape, StorageFormat f, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 4.0f);
    ProbeTexture t = ProbeTexture::make(shape);
    for (float& v : t.texels)
        v = u(rng);
    quantise(t, f);
    return t;
}

// A small bake of a built-in scene: one root volume over the static bounds.
ProbeSet bakeBuiltin(const std::string& name, int maxProbes, bool sparse,
                     FreeSpace freeSpace = FreeSpace::StandIns) {
    const pb::scene::Scene s = pb::scene::makeBuiltinScene(name);
    BakeRequest r;
    r.volumes.push_back(fitAutoVolume(pb::raytrace::staticBakeBounds(s), 0.0f, maxProbes).volume);
    r.scenarios = resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 1;
    r.sparse = sparse;
    r.freeSpace = freeSpace;
    return bakeProbes(s, r);
}

const ProbeSet& courtyardDense() {
    static const ProbeSet set = bakeBuiltin("courtyard", 1500, false);
    return set;
}

} // namespace

TEST(SparseLayout, AllStoredPacksToTheDenseGrid) {
    for (glm::ivec3 c : {glm::ivec3(1, 1, 1), glm::ivec3(5, 3, 4), glm::ivec3(17, 6, 9)})
        EXPECT_EQ(packedCounts(std::size_t(c.x * c.y * c.z), c), c);
}

TEST(SparseLayout, PackedGridHoldsEveryStoredTileInNoLargerLayers) {
    const glm::ivec3 dense(7, 5, 6);
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(6), std::size_t(7),
                          std::size_t(43), std::size_t(100), std::size_t(209)}) {
        const glm::ivec3 p = packedCounts(n, dense);
        EXPECT_GE(std::size_t(p.x * p.y * p.z), std::max<std::size_t>(n, 1)) << n;
        EXPECT_LE(p.x, dense.x) << n;
        EXPECT_LE(p.z, dense.z) << n;
        EXPECT_LE(p.y, dense.y) << n;
    }
}

TEST(SparseLayout, PackThenUnpackKeepsStoredTilesAndZeroesTheRest) {
    const glm::ivec3 counts(3, 2, 4);
    std::vector<ProbeState> states(24);
    for (std::size_t i = 0; i < states.size(); ++i)
        states[i].stored = (i * 7) % 3 != 0;
    const std::vector<int> slots = packedSlots(states);
    const glm::ivec3 packed = packedCounts(storedCount(states), counts);
    ASSERT_LT(storedCount(states), states.size());
    ProbeVolume grid;
    grid.counts = counts;
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Rgba32f, StorageFormat::Bc6h}) {
        for (bool irradiance : {true, false}) {
            const int tile = irradiance ? kIrradianceTile : kVisibilityTile;
            const TextureShape shape =
                irradiance ? irradianceShape(counts) : visibilityShape(counts);
            const ProbeTexture dense = randomTexture(shape, f, 7u + unsigned(f));
            const ProbeTexture p = packTiles(dense, slots, counts, packed, tile, f);
            EXPECT_LT(p.stored.size(), dense.stored.size());
            const ProbeTexture back = unpackTiles(p, slots, counts, packed, tile, f);
            ASSERT_EQ(back.shape, dense.shape);
            ASSERT_EQ(back.texels.size(), dense.texels.size());
            for (int i = 0; i < grid.probeCount(); ++i) {
                const glm::ivec3 q = grid.probeCoords(i);
                for (int row = 0; row < tile; ++row)
                    for (int col = 0; col < tile; ++col) {
                        const float* a = back.at(q.x * tile + col, q.z * tile + row, q.y);
                        const float* b = dense.at(q.x * tile + col, q.z * tile + row, q.y);
                        // Absent tiles are zero bytes: RGB 0 (BC6H reads alpha back as 1).
                        for (int ch = 0; ch < std::min(shape.channels, 3); ++ch)
                            ASSERT_EQ(a[ch], states[size_t(i)].stored ? b[ch] : 0.0f)
                                << formatName(f) << " probe " << i;
                    }
            }
        }
    }
}

TEST(SparseLayout, ZeroingInPlaceGivesThePackUnpackRoundTrip) {
    // Sparse storage zeroes the absent tiles in place instead of packing and unpacking: the
    // bytes and texels must be those of the round trip, in every format.
    const glm::ivec3 counts(3, 2, 4);
    std::vector<ProbeState> states(24);
    for (std::size_t i = 0; i < states.size(); ++i)
        states[i].stored = (i * 5) % 4 != 1;
    const std::vector<int> slots = packedSlots(states);
    const glm::ivec3 packed = packedCounts(storedCount(states), counts);
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Rgba32f, StorageFormat::Bc6h})
        for (bool irradiance : {true, false}) {
            const int tile = irradiance ? kIrradianceTile : kVisibilityTile;
            const TextureShape shape =
                irradiance ? irradianceShape(counts) : visibilityShape(counts);
            ProbeTexture inPlace = randomTexture(shape, f, 11u + unsigned(f));
            const ProbeTexture roundTrip = unpackTiles(
                packTiles(inPlace, slots, counts, packed, tile, f), slots, counts, packed, tile, f);
            zeroUnslottedTiles(inPlace, slots, counts, tile, f);
            EXPECT_EQ(inPlace.stored, roundTrip.stored) << formatName(f) << " tile " << tile;
            EXPECT_EQ(inPlace.texels, roundTrip.texels) << formatName(f) << " tile " << tile;
            EXPECT_EQ(inPlace.shape, roundTrip.shape);
        }
    ProbeTexture wrong = randomTexture(irradianceShape(counts), StorageFormat::Rgba16f, 3u);
    EXPECT_THROW(zeroUnslottedTiles(wrong, slots, counts, kVisibilityTile, StorageFormat::Rgba16f),
                 pb::Error);
}

// One small triangle inside cell (1, 1, 1) of a 5x5x5 grid with unit cells: exactly that
// cell's 8 corners are kept. A triangle in a root's fade margin keeps its boundary cell.
TEST(SparseStorage, KeepsExactlyTheCornersOfSurfaceCells) {
    ProbeVolume v;
    v.name = "v";
    v.halfExtents = glm::vec3(2.0f);
    v.counts = glm::ivec3(5);
    const glm::vec3 o(-2.0f); // probe (0,0,0)
    pb::raytrace::WorldTriangle t{o + glm::vec3(1.2f, 1.3f, 1.4f), o + glm::vec3(1.6f, 1.3f, 1.5f),
                    o + glm::vec3(1.4f, 1.7f, 1.6f), glm::vec3(0, 0, 1)};
    std::vector<std::uint8_t> kept = surfaceCornerProbes(v, true, {t});
    for (int i = 0; i < v.probeCount(); ++i) {
        const glm::ivec3 q = v.probeCoords(i);
        const bool corner = glm::all(glm::greaterThanEqual(q, glm::ivec3(1))) &&
                            glm::all(glm::lessThanEqual(q, glm::ivec3(2)));
        EXPECT_EQ(kept[size_t(i)] != 0, corner) << q.x << "," << q.y << "," << q.z;
    }
    // 0.3 cells beyond the +x face: within a root's fade (0.5 cells), outside a child's box.
    pb::raytrace::WorldTriangle out = t;
    out.a.x = out.b.x = out.c.x = 2.3f; // the +x face is at 2, cells are 1 long
    kept = surfaceCornerProbes(v, true, {out});
    EXPECT_EQ(std::count(kept.begin(), kept.end(), 1), 8);
    EXPECT_TRUE(kept[size_t(v.probeIndex({4, 1, 1}))] && kept[size_t(v.probeIndex({3, 2, 2}))]);
    kept = surfaceCornerProbes(v, false, {out});
    EXPECT_EQ(std::count(kept.begin(), kept.end(), 1), 0);
}

// Many triangles (several work items, so several threads on a multi-core machine): the mask
// is the union of what each triangle marks alone, whichever thread saw it. The volume is
// rotated, so the general transform runs; the next test covers the axis-aligned one.
TEST(SparseStorage, ManyTrianglesMarkTheUnionOfTheirOwnCells) {
    ProbeVolume v;
    v.name = "v";
    v.halfExtents = glm::vec3(4.0f, 3.0f, 5.0f);
    v.counts = glm::ivec3(9, 7, 11);
    v.rotation = rotationFromEulerDegrees(glm::vec3(10.0f, 35.0f, 0.0f));
    std::mt19937 rng(17);
    // Only the world's -x half holds triangles, so part of the volume stays empty.
    std::uniform_real_distribution<float> pos(-6.0f, 6.0f), half(-6.0f, -1.0f), edge(-0.6f, 0.6f);
    std::vector<pb::raytrace::WorldTriangle> tris;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 a(half(rng), pos(rng), pos(rng));
        tris.push_back({a, a + glm::vec3(edge(rng), edge(rng), edge(rng)),
                        a + glm::vec3(edge(rng), edge(rng), edge(rng)), glm::vec3(0, 1, 0)});
    }
    const std::vector<std::uint8_t> all = surfaceCornerProbes(v, true, tris);
    std::vector<std::uint8_t> expected(all.size(), 0);
    for (const pb::raytrace::WorldTriangle& t : tris) {
        const std::vector<std::uint8_t> one = surfaceCornerProbes(v, true, {t});
        for (std::size_t i = 0; i < one.size(); ++i)
            expected[i] |= one[i];
    }
    EXPECT_EQ(all, expected);
    const auto kept = std::count(all.begin(), all.end(), std::uint8_t(1));
    EXPECT_GT(kept, 0);
    EXPECT_LT(kept, v.probeCount());
}

// An axis-aligned volume skips the rotation (SparseStorage.cpp): the quaternion -1, the same
// rotation written the other way, takes the general transform and must mark the same probes.
TEST(SparseStorage, AxisAlignedShortcutMarksWhatTheRotationMarks) {
    ProbeVolume v;
    v.name = "v";
    v.center = glm::vec3(0.3f, -0.2f, 0.1f);
    v.halfExtents = glm::vec3(4.0f, 3.0f, 5.0f);
    v.counts = glm::ivec3(17, 13, 21);
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> pos(-5.5f, 5.5f), edge(-0.4f, 0.4f);
    std::vector<pb::raytrace::WorldTriangle> tris;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 a(pos(rng), pos(rng), pos(rng));
        tris.push_back({a, a + glm::vec3(edge(rng), edge(rng), edge(rng)),
                        a + glm::vec3(edge(rng), edge(rng), edge(rng)), glm::vec3(0, 1, 0)});
    }
    ProbeVolume flipped = v;
    flipped.rotation = glm::quat(-1.0f, 0.0f, 0.0f, 0.0f);
    for (bool root : {true, false}) {
        const std::vector<std::uint8_t> aligned = surfaceCornerProbes(v, root, tris);
        EXPECT_EQ(aligned, surfaceCornerProbes(flipped, root, tris)) << "root " << root;
        EXPECT_GT(std::count(aligned.begin(), aligned.end(), std::uint8_t(1)), 0);
    }
}

// What the guarantee rests on: a surface point reads only the corners of its cell, and those
// are kept, so dropping the rest changes no surface's irradiance - bit for bit.
TEST(SparseStorage, DroppingFarProbesChangesNoSurfaceIrradiance) {
    const pb::scene::Scene scene = pb::scene::makeBuiltinScene("courtyard");
    const ProbeSet& dense = courtyardDense();
    ProbeSet sparse = dense;
    const std::vector<pb::raytrace::WorldTriangle> triangles = pb::raytrace::staticBakeTriangles(scene);
    applySparseStorage(sparse, triangles);
    const std::size_t stored = sparse.storedCount(),
                      valid = dense.probeCount() - dense.invalidCount();
    std::printf("[ sparse ] courtyard: %zu of %zu probes stored (%zu valid)\n", stored,
                dense.probeCount(), valid);
    EXPECT_LT(stored, valid) << "nothing far from the surfaces was dropped: the test is vacuous";
    EXPECT_GT(stored, 0u);

    std::vector<float> areas;
    for (const pb::raytrace::WorldTriangle& t : triangles)
        areas.push_back(t.area());
    std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ProbeSampler a(dense, 0), b(sparse, 0);
    int lit = 0;
    for (int i = 0; i < 4000; ++i) {
        const pb::raytrace::WorldTriangle& t = triangles[pick(rng)];
        float r1 = u(rng), r2 = u(rng);
        if (r1 + r2 > 1.0f) r1 = 1.0f - r1, r2 = 1.0f - r2;
        const glm::vec3 p = t.a + r1 * (t.b - t.a) + r2 * (t.c - t.a);
        const glm::vec3 view = glm::normalize(t.normal + glm::vec3(u(rng), u(rng), u(rng)) - 0.5f);
        const IrradianceSample x = a.sample(p, t.normal, view), y = b.sample(p, t.normal, view);
        ASSERT_EQ(x.weight, y.weight) << i;
        ASSERT_EQ(x.irradiance, y.irradiance) << i << " at " << p.x << "," << p.y << "," << p.z;
        lit += x.weight > 0.0f ? 1 : 0;
    }
    EXPECT_GT(lit, 3000);
}

// A sparse bake traces radiance only for the probes it keeps (and every probe of a parent
// volume): that must give exactly the dense bake with the others dropped afterwards, over
// two bounces (the second pass looks the first up) and with a nested child (ring blend).
TEST(SparseStorage, BakingOnlyTheKeptProbesGivesTheDenseBakeDropped) {
    const pb::scene::Scene s = pb::scene::makeBuiltinScene("courtyard");
    BakeRequest r;
    ProbeVolume outer = fitAutoVolume(pb::raytrace::staticBakeBounds(s), 0.0f, 900).volume;
    ProbeVolume child = outer;
    child.name = "child";
    child.parent = outer.name;
    child.halfExtents = outer.halfExtents * 0.45f;
    child.counts = glm::max(outer.counts / 2 + 1, glm::ivec3(2));
    r.volumes = {outer, child};
    r.scenarios = resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 2;
    const ProbeSet denseBake = bakeProbes(s, r);
    // Both storages of the probes left out: dropped (stand-ins), or their irradiance kept
    // (traced in the last pass: the earlier passes feed only surface lookups, whose corners
    // are all kept, so their irradiance and SH are the dense bake's).
    // Ranked keeps some of them (the default budget: the tiles get 5% of the whole).
    for (FreeSpace mode : {FreeSpace::StandIns, FreeSpace::Ranked, FreeSpace::Irradiance}) {
    SCOPED_TRACE(freeSpaceName(mode));
    ProbeSet dense = denseBake;
    applySparseStorage(dense, pb::raytrace::staticBakeTriangles(s), mode);
    const std::size_t tiles = memoryReport(dense).total.irradianceOnlyProbes;
    if (mode == FreeSpace::StandIns) {
        EXPECT_EQ(tiles, 0u);
    }
    if (mode != FreeSpace::StandIns) {
        EXPECT_GT(tiles, 0u);
    }
    r.sparse = true;
    r.freeSpace = mode;
    const ProbeSet sparse = bakeProbes(s, r);
    ASSERT_LT(sparse.storedCount(), sparse.probeCount()) << "nothing dropped: vacuous";
    for (std::size_t v = 0; v < 2; ++v) {
        for (std::size_t i = 0; i < dense.states[v].size(); ++i) {
            EXPECT_EQ(sparse.states[v][i].stored, dense.states[v][i].stored) << v << "/" << i;
            EXPECT_EQ(sparse.states[v][i].irradianceOnly, dense.states[v][i].irradianceOnly)
                << v << "/" << i;
            EXPECT_EQ(sparse.states[v][i].offset, dense.states[v][i].offset) << v << "/" << i;
        }
        EXPECT_EQ(sparse.visibility[v].stored, dense.visibility[v].stored) << v;
        EXPECT_EQ(sparse.irradiance[0][v].stored, dense.irradiance[0][v].stored) << v;
    }
    EXPECT_EQ(sparse.sh, dense.sh);
    }
}

// The parent exception: a child's ring probe blends towards the parent at its own position,
// which may fall in a parent cell no surface passes through. Here a floor at y = 0.7 lies in
// the parent cell [-1.25, 0.75]; the child's top ring (y = 1.0, kept: its cell holds the
// floor) reads the parent cell [0.75, 2.75], whose upper corners no surface keeps.
TEST(SparseStorage, ParentVolumesKeepTheRadianceTheirChildRingsRead) {
    pb::scene::Scene s = pb::test::emptyScene(glm::vec3(0.4f, 0.5f, 0.7f));
    s.sun.enabled = true;
    const int m = pb::test::addMaterial(s, glm::vec3(0.6f));
    pb::scene::Primitive floor;
    floor.material = m;
    pb::test::addQuad(floor, {-4, 0.7f, -4}, {8, 0, 0}, {0, 0, 8}, {0, 1, 0});
    pb::test::addInstance(s, floor);
    ProbeVolume parent, child;
    parent.name = "parent";
    parent.center = {0, 3.75f, 0};
    parent.halfExtents = {4, 5, 4};
    parent.counts = {5, 6, 5};
    child.name = "child";
    child.parent = "parent";
    child.center = {0, 0.75f, 0};
    child.halfExtents = {1, 0.25f, 1};
    child.counts = {3, 2, 3};
    BakeRequest r;
    r.volumes = {parent, child};
    r.scenarios = resolveScenarios({"day"}, {}, s);
    r.settings.raysPerProbe = 32;
    r.settings.bounces = 1;
    r.settings.relocate = false;
    ProbeSet dense = bakeProbes(s, r);
    applySparseStorage(dense, pb::raytrace::staticBakeTriangles(s));
    // x = -2, y = 2.75 (off the free-space lattice: x is odd)
    ASSERT_FALSE(dense.states[0][size_t(parent.probeIndex({1, 2, 2}))].stored);
    ASSERT_TRUE(dense.states[1][size_t(child.probeIndex({1, 1, 1}))].stored); // y = 1.0
    r.sparse = true;
    const ProbeSet sparse = bakeProbes(s, r);
    EXPECT_EQ(sparse.irradiance[0][1].stored, dense.irradiance[0][1].stored);
    EXPECT_EQ(sparse.irradiance[0][0].stored, dense.irradiance[0][0].stored);
}

// Issue 18: an absent probe outside geometry is read as its nearest stored probe, so every
// point of the box that the dense set lights gets a lookup; an absent probe inside geometry
// stays invalid (the dense set skips it too).
TEST(SparseStorage, AbsentProbesReadTheirNearestStoredProbe) {
    const ProbeSet& dense = courtyardDense();
    ProbeSet sparse = dense;
    applySparseStorage(sparse, pb::raytrace::staticBakeTriangles(pb::scene::makeBuiltinScene("courtyard")));
    const ProbeVolume& v = dense.volumes[0];
    const std::vector<int> source =
        fillSources(v, sparse.states[0], sparse.settings.backfaceThreshold);
    ASSERT_EQ(source.size(), sparse.states[0].size()) << "nothing to fill: vacuous";
    int filled = 0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const ProbeState& s = sparse.states[0][i];
        if (s.stored || !dense.states[0][i].valid) {
            EXPECT_EQ(source[i], int(i)) << "stored or inside geometry, yet filled: " << i;
            continue;
        }
        ++filled;
        ASSERT_GE(source[i], 0);
        const ProbeState& from = sparse.states[0][size_t(source[i])];
        EXPECT_TRUE(from.stored && from.valid) << i;
        // Nearest: no stored probe is closer to the absent probe's grid point.
        const glm::vec3 at = v.gridLocal(v.probeCoords(int(i)));
        const float d = glm::length(v.gridLocal(v.probeCoords(source[i])) - at);
        for (std::size_t j = 0; j < source.size(); ++j)
            if (sparse.states[0][j].stored && sparse.states[0][j].valid) {
                ASSERT_GE(glm::length(v.gridLocal(v.probeCoords(int(j))) - at), d - 1e-4f)
                    << "probe " << i << ": " << j << " is nearer than " << source[i];
            }
    }
    EXPECT_GT(filled, 0);

    ProbeSampler a(dense, 0), b(sparse, 0);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int standIns = 0;
    for (int i = 0; i < 3000; ++i) { // anywhere in the box: surfaces and empty air
        const glm::vec3 p = v.toWorld(glm::vec3(u(rng), u(rng), u(rng)) * v.halfExtents);
        const glm::vec3 n = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
        const IrradianceSample x = a.sample(p, n, n), y = b.sample(p, n, n);
        ASSERT_EQ(x.weight > 0.0f, y.weight > 0.0f) << "at " << p.x << "," << p.y << "," << p.z;
        standIns += y.filled > 0 ? 1 : 0;
    }
    EXPECT_GT(standIns, 0) << "no lookup read a stand-in";
}

// The coarse free-space lattice is kept whatever the surfaces: every probe whose coordinates
// are all even, and no other probe of an empty volume.
TEST(SparseStorage, KeepsTheFreeSpaceLatticeEverywhere) {
    ProbeVolume v;
    v.name = "v";
    v.halfExtents = glm::vec3(2.0f, 1.0f, 3.0f);
    v.counts = glm::ivec3(5, 4, 7);
    const std::vector<std::uint8_t> kept = sparseKeptProbes(v, true, {});
    for (int i = 0; i < v.probeCount(); ++i) {
        const glm::ivec3 q = v.probeCoords(i);
        EXPECT_EQ(kept[size_t(i)] != 0, q.x % 2 == 0 && q.y % 2 == 0 && q.z % 2 == 0) << i;
    }
}

// The default bake's mix (FreeSpace::Ranked): some left-out probes keep a tile, the others
// are read as stand-ins - and read back from the file, each is what it was, and the counts
// tell both apart from the probes inside geometry.
TEST(SparseStorage, FileRoundTripKeepsTheRankedMixOfTilesAndStandIns) {
    const ProbeSet sparse = bakeBuiltin("courtyard", 1500, true, FreeSpace::Ranked);
    const ProbeSet back = parseProbeSet(serializeProbeSet(sparse), "ranked.pbp");
    std::size_t tiles = 0, standIns = 0;
    for (std::size_t i = 0; i < back.states[0].size(); ++i) {
        EXPECT_EQ(back.states[0][i].stored, sparse.states[0][i].stored) << i;
        EXPECT_EQ(back.states[0][i].irradianceOnly, sparse.states[0][i].irradianceOnly) << i;
        EXPECT_EQ(back.states[0][i].valid, sparse.states[0][i].valid) << i;
        tiles += back.states[0][i].irradianceOnly ? 1 : 0;
        standIns += fillable(back.states[0][i], back.settings.backfaceThreshold) ? 1 : 0;
    }
    ASSERT_GT(tiles, 0u) << "no tile: not a mix";
    ASSERT_GT(standIns, 0u) << "no stand-in: not a mix";
    EXPECT_EQ(back.irradiance[0][0].texels, sparse.irradiance[0][0].texels);
    EXPECT_EQ(back.sh, sparse.sh);
    // The free-space record: what the input hash was made of, so the file is still known as
    // this scene's (render, costmodel and bench check it).
    EXPECT_EQ(back.freeSpace, FreeSpace::Ranked);
    EXPECT_EQ(back.freeSpaceBudgetBytes, 0.0);
    EXPECT_TRUE(probeSetMatchesScene(back, pb::scene::makeBuiltinScene("courtyard")));
    EXPECT_FALSE(probeSetMatchesScene(back, pb::scene::makeBuiltinScene("rooms")));
    // Read back, the probes not stored split as the bake counted them.
    const ProbeSet& dense = courtyardDense();
    std::size_t inside = 0;
    for (const ProbeState& p : dense.states[0])
        inside += p.valid ? 0 : 1;
    const ProbeCounts c = volumeProbeCounts(back, nullptr)[0];
    EXPECT_EQ(c.absent, tiles + standIns);
    EXPECT_EQ(c.invalid, inside);
}

// A version 7 file (no free-space record) reads as what its states imply - all when it has
// irradiance-only probes - and its input hash, made then of exactly that, still matches its
// scene and the bake of the same request (the bake cache keeps it).
TEST(SparseStorage, AVersion7FileReadsItsFreeSpaceFromItsStates) {
    const pb::scene::Scene scene = pb::scene::makeBuiltinScene("courtyard");
    const ProbeSet sparse = bakeBuiltin("courtyard", 1500, true, FreeSpace::Irradiance);
    // Version 7 had no free-space record (u8 + f64).
    const std::vector<std::uint8_t> bytes =
        pb::test::asOlderProbeFile(serializeProbeSet(sparse), 9, 7);
    const ProbeSet old = parseProbeSet(bytes, "v7.pbp");
    EXPECT_EQ(old.freeSpace, FreeSpace::Irradiance);
    EXPECT_EQ(old.freeSpaceBudgetBytes, 0.0);
    EXPECT_EQ(old.inputHash, sparse.inputHash);
    EXPECT_TRUE(probeSetMatchesScene(old, scene));
}

TEST(SparseStorage, FileRoundTripStoresOnlyTheKeptTiles) {
    ProbeSet sparse = bakeBuiltin("courtyard", 1500, true, FreeSpace::Irradiance);
    ASSERT_LT(sparse.storedCount(), sparse.probeCount());
    const std::vector<std::uint8_t> bytes = serializeProbeSet(sparse);
    const ProbeSet back = parseProbeSet(bytes, "sparse.pbp");
    ASSERT_EQ(back.states[0].size(), sparse.states[0].size());
    std::size_t irradianceOnly = 0;
    for (std::size_t i = 0; i < back.states[0].size(); ++i) {
        EXPECT_EQ(back.states[0][i].stored, sparse.states[0][i].stored);
        EXPECT_EQ(back.states[0][i].irradianceOnly, sparse.states[0][i].irradianceOnly);
        EXPECT_EQ(back.states[0][i].valid, sparse.states[0][i].valid);
        irradianceOnly += sparse.states[0][i].irradianceOnly ? 1 : 0;
    }
    ASSERT_GT(irradianceOnly, 0u) << "no irradiance-only probe: vacuous";
    EXPECT_EQ(back.sh, sparse.sh);
    EXPECT_EQ(back.visibility[0].texels, sparse.visibility[0].texels);
    EXPECT_EQ(back.visibility[0].stored, sparse.visibility[0].stored);
    EXPECT_EQ(back.irradiance[0][0].texels, sparse.irradiance[0][0].texels);
    // The file shrinks with the stored share; the memory report counts the packed tiles and
    // the indirection.
    ProbeSet allStored = sparse;
    for (ProbeState& p : allStored.states[0])
        p.stored = true;
    const std::size_t denseSize = serializeProbeSet(allStored).size();
    // An irradiance-only probe costs its irradiance tile: 8x8 rgba16f texels of a stored
    // probe's 8x8 + 16x16 rg16f, a third.
    const double share = 512.0 / (512.0 + 1024.0);
    EXPECT_LT(double(bytes.size()),
              double(denseSize) *
                  (double(sparse.storedCount()) + share * double(irradianceOnly) + 64.0) /
                  double(sparse.probeCount()));
    const MemoryReport mem = memoryReport(back);
    EXPECT_EQ(mem.total.storedProbes, sparse.storedCount());
    EXPECT_EQ(mem.total.irradianceOnlyProbes, irradianceOnly);
    EXPECT_EQ(mem.total.indirection, sparse.probeCount() * kStateBytesPerProbe);
    EXPECT_LT(mem.total.storedTotal(), memoryReport(allStored).total.storedTotal());
    // The bake keeps exactly the valid probes among those placement's budget counts.
    const std::vector<std::uint8_t> corners = sparseKeptProbes(
        sparse.volumes[0], true, pb::raytrace::staticBakeTriangles(pb::scene::makeBuiltinScene("courtyard")));
    const ProbeSet& dense = courtyardDense(); // the same bake, stored dense
    for (std::size_t i = 0; i < corners.size(); ++i)
        ASSERT_EQ(sparse.states[0][i].stored, corners[i] && dense.states[0][i].valid) << i;
}

// A crafted storage record with a valid checksum is a one-line error, never a crash.
TEST(SparseStorage, CorruptStorageRecordIsAClearError) {
    ProbeSet set = bakeBuiltin("cornell", 64, false);
    for (std::size_t i = 0; i < set.states[0].size(); i += 3)
        set.states[0][i].stored = set.states[0][i].valid = false;
    const std::vector<std::uint8_t> good = serializeProbeSet(set);
    ASSERT_NO_THROW(parseProbeSet(good, "p.pbp"));
    // The record follows the probe states: find "layout 1, u32 stored count".
    const std::uint32_t count = std::uint32_t(set.storedCount());
    std::size_t at = std::string::npos;
    for (std::size_t i = 0; i + 5 < good.size() && at == std::string::npos; ++i)
        if (good[i] == 1 && std::memcmp(&good[i + 1], &count, 4) == 0 && i > 100) at = i;
    ASSERT_NE(at, std::string::npos);
    auto broken = [&](std::size_t offset, std::uint8_t value) {
        std::vector<std::uint8_t> b = good;
        b[offset] = value;
        const std::uint64_t sum = pb::fnv1a64(b.data(), b.size() - 8);
        std::memcpy(b.data() + b.size() - 8, &sum, 8);
        try {
            parseProbeSet(b, "p.pbp");
        } catch (const pb::Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    const std::string layout = broken(at, 7);
    EXPECT_NE(layout.find("p.pbp: corrupt storage"), std::string::npos) << layout;
    const std::string counted = broken(at + 1, std::uint8_t(count + 1));
    EXPECT_NE(counted.find("stored probes declared"), std::string::npos) << counted;
    const std::string bits = broken(at + 5, std::uint8_t(good[at + 5] ^ 0x02));
    EXPECT_EQ(bits.find('\n'), std::string::npos);
    EXPECT_NE(bits.find("p.pbp: "), std::string::npos) << bits;
}

// The bytes of the committed sparse seed
// (tests/data/fuzz-seeds/probe_file/courtyard_sparse_bc6h.pbp), flipped, with size and checksum
// made to match, through the fuzzers' contract: it loads (and samples finite) or is a one-line
// error naming the file.
TEST(SparseStorage, EveryFlippedByteOfASparseFileKeepsTheErrorContract) {
    const std::vector<std::uint8_t> seed = pb::readFileBytes(
        (pb::test::sourceDir() / "tests/data/fuzz-seeds/probe_file/courtyard_sparse_bc6h.pbp")
            .string());
    ASSERT_GT(seed.size(), 100u);
    ASSERT_LT(parseProbeSet(seed, "seed.pbp").storedCount(),
              parseProbeSet(seed, "seed.pbp").probeCount());
    // Every byte of the header, volumes, states and storage record; a sample of the texels.
    int rejected = 0;
    for (std::size_t i = 0; i < seed.size(); i += i < 2048 ? 1 : 11)
        for (std::uint8_t flip : {std::uint8_t(0x01), std::uint8_t(0xFF)}) {
            std::vector<std::uint8_t> b = seed;
            b[i] ^= flip;
            ASSERT_NO_THROW(rejected += pb::fuzz::runProbeFile(b.data(), b.size()) ==
                                        pb::fuzz::Outcome::Rejected)
                << "byte " << i;
        }
    EXPECT_GT(rejected, 0);
}
