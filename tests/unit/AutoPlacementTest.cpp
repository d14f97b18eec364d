// Automatic probe placement (`--volumes auto`): box merging, the adaptive octree, nesting,
// the memory budget, determinism and the volumes-file round trip.
#include "probes/placement/AutoPlacement.h"
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "probes/placement/BoxMerge.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/MemoryReport.h"
#include "raytrace/RayScene.h"
#include "raytrace/StaticTriangles.h"
#include "probes/store/VolumeFile.h"
#include "scene/SceneLoader.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::probes;
using pb::test::addInstance;
using pb::test::addMaterial;
using pb::test::boxPrimitive;

namespace {

// A 40 x 40 floor at y = 0 (a flat box) and one 1 m block floating at (12, 10, 12), far from it.
pb::scene::Scene floorAndFarBlock() {
    pb::scene::Scene s = pb::test::emptyScene();
    int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-20.0f, -0.2f, -20.0f}, {20.0f, 0.0f, 20.0f}, false, m));
    addInstance(s, boxPrimitive({11.5f, 9.5f, 11.5f}, {12.5f, 10.5f, 12.5f}, false, m));
    return s;
}

AutoPlacementRequest adaptiveRequest(float spacing) {
    AutoPlacementRequest r;
    r.adaptive.spacing = spacing;
    r.maxProbes = 1 << 20;
    return r;
}

// Volumes containing `p` (the box, no margin).
std::vector<const ProbeVolume*> volumesAt(const std::vector<ProbeVolume>& vs, glm::vec3 p) {
    std::vector<const ProbeVolume*> out;
    for (const ProbeVolume& v : vs)
        if (v.contains(p)) out.push_back(&v);
    return out;
}

float spacingOf(const ProbeVolume& v) {
    glm::vec3 c = v.cellSize();
    return std::max(c.x, std::max(c.y, c.z));
}

// Every surface point (triangle corners and centroids) lies in a volume at the finest spacing.
void expectSurfacesAtFinestSpacing(const pb::scene::Scene& s, const AutoPlacementResult& r) {
    float finest = spacingOf(r.volumes[0]);
    for (const ProbeVolume& v : r.volumes)
        finest = std::min(finest, spacingOf(v));
    for (const pb::raytrace::WorldTriangle& t : pb::raytrace::staticBakeTriangles(s))
        for (glm::vec3 p : {t.a, t.b, t.c, (t.a + t.b + t.c) / 3.0f}) {
            float best = std::numeric_limits<float>::infinity();
            for (const ProbeVolume* v : volumesAt(r.volumes, p))
                best = std::min(best, spacingOf(*v));
            ASSERT_LE(best, finest * 1.0001f) << s.name << ": surface point " << p.x << "," << p.y
                                              << "," << p.z << " not at the finest spacing";
        }
}

} // namespace

TEST(BoxMerge, NothingMarkedGivesNoBox) {
    glm::ivec3 dims(4, 4, 4);
    EXPECT_TRUE(mergeMarkedCells(dims, std::vector<std::uint8_t>(64, 0)).empty());
}

TEST(BoxMerge, DenseBlockStaysOneTightBox) {
    glm::ivec3 dims(10, 6, 8);
    std::vector<std::uint8_t> m(std::size_t(dims.x * dims.y * dims.z), 0);
    for (int z = 2; z < 7; ++z)
        for (int y = 1; y < 5; ++y)
            for (int x = 3; x < 9; ++x)
                m[cellIndex(dims, {x, y, z})] = 1;
    auto boxes = mergeMarkedCells(dims, m, {8, 1, 0.05});
    ASSERT_EQ(boxes.size(), 1u);
    EXPECT_EQ(boxes[0].lo, glm::ivec3(3, 1, 2));
    EXPECT_EQ(boxes[0].hi, glm::ivec3(9, 5, 7));
}

TEST(BoxMerge, SeparateClustersGetSeparateBoxesCoveringEveryCell) {
    glm::ivec3 dims(40, 20, 40);
    std::vector<std::uint8_t> m(std::size_t(dims.x * dims.y * dims.z), 0);
    for (int z = 0; z < 40; ++z) // a floor slab
        for (int x = 0; x < 40; ++x)
            m[cellIndex(dims, {x, 0, z})] = 1;
    for (int z = 30; z < 32; ++z) // a small block high above it
        for (int y = 15; y < 17; ++y)
            for (int x = 30; x < 32; ++x)
                m[cellIndex(dims, {x, y, z})] = 1;
    auto boxes = mergeMarkedCells(dims, m, {4, 1, 0.05});
    ASSERT_EQ(boxes.size(), 2u);
    double probes = 0;
    for (const CellBox& b : boxes)
        probes += boxProbeCost(b.size(), 1);
    EXPECT_LT(probes, 0.2 * boxProbeCost(dims, 1)) << "the air between them is not covered";
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) {
                if (!m[cellIndex(dims, {x, y, z})]) continue;
                int inside = 0;
                for (const CellBox& b : boxes)
                    inside += glm::all(glm::greaterThanEqual(glm::ivec3(x, y, z), b.lo)) &&
                              glm::all(glm::lessThan(glm::ivec3(x, y, z), b.hi));
                ASSERT_EQ(inside, 1) << "cell " << x << "," << y << "," << z;
            }
    auto one = mergeMarkedCells(dims, m, {1, 1, 0.05});
    EXPECT_EQ(one.size(), 1u) << "maxBoxes is respected";
}

TEST(AutoPlacement, ChildNearTheFarBlockAndNoneInEmptyAir) {
    pb::scene::Scene s = floorAndFarBlock();
    AutoPlacementResult r = placeAutoVolumes(s, adaptiveRequest(0.5f));
    ASSERT_GE(r.volumes.size(), 2u);
    EXPECT_NO_THROW(validateVolumes(r.volumes, "auto"));
    EXPECT_TRUE(r.volumes[0].parent.empty());
    EXPECT_EQ(r.volumes[0].name, "auto");

    // The block is inside a child whose box stays near it (it does not reach down to the floor).
    const ProbeVolume* blockChild = nullptr;
    for (const ProbeVolume* v : volumesAt(r.volumes, {12.0f, 10.0f, 12.0f}))
        if (!v->parent.empty() && (!blockChild || v->boxVolume() < blockChild->boxVolume()))
            blockChild = v;
    ASSERT_NE(blockChild, nullptr) << "no child volume around the block";
    EXPECT_GT(blockChild->center.y - blockChild->halfExtents.y, 5.0f);
    EXPECT_LT(blockChild->boxVolume(), 0.01f * r.volumes[0].boxVolume());
    // Mid-air points far from both surfaces are covered by the outer volume only.
    for (glm::vec3 p : {glm::vec3(-10.0f, 6.0f, -10.0f), glm::vec3(0.0f, 8.0f, 0.0f),
                        glm::vec3(12.0f, 5.0f, -12.0f)})
        EXPECT_EQ(volumesAt(r.volumes, p).size(), 1u) << p.x << "," << p.y << "," << p.z;
    expectSurfacesAtFinestSpacing(s, r);
}

TEST(AutoPlacement, EveryChildLiesInsideItsParent) {
    for (const char* name : {"courtyard", "rooms", "cornell"}) {
        pb::scene::Scene s = pb::scene::loadScene(name);
        AutoPlacementResult r = placeAutoVolumes(s, AutoPlacementRequest{});
        std::vector<int> parents = validateVolumes(r.volumes, name);
        for (std::size_t i = 0; i < r.volumes.size(); ++i) {
            if (parents[i] < 0) continue;
            EXPECT_EQ(nestingProblem(r.volumes[i], r.volumes[size_t(parents[i])]), "") << name;
            // Child probes sit on the parent's lattice at a finer spacing.
            EXPECT_LT(spacingOf(r.volumes[i]), spacingOf(r.volumes[size_t(parents[i])])) << name;
        }
        EXPECT_EQ(std::count(parents.begin(), parents.end(), -1), 1) << name << ": one root";
    }
}

TEST(AutoPlacement, BuiltinScenesGetFineProbesWhereTheGeometryIs) {
    // The octree's tiers, not where the lattice search shifts them (EveryChildLiesInsideItsParent
    // places with the search; LatticeSearchOnlyShiftsWithinTheBudgetAndIsDeterministic tests it).
    AutoPlacementRequest req;
    req.latticeSearch = false;
    for (const char* name : {"courtyard", "rooms", "cornell"}) {
        pb::scene::Scene s = pb::scene::loadScene(name);
        AutoPlacementResult r = placeAutoVolumes(s, req);
        expectSurfacesAtFinestSpacing(s, r);
    }
    // rooms is enclosed (every cell is near a wall): the interiors get the finest spacing,
    // as one grid rather than a coarse volume duplicated by a child of the same box.
    pb::scene::Scene rooms = pb::scene::loadScene("rooms");
    AutoPlacementResult r = placeAutoVolumes(rooms, adaptiveRequest(0.2f));
    for (glm::vec3 p : {glm::vec3(-2.0f, 1.2f, 0.0f), glm::vec3(2.0f, 1.2f, 0.0f)}) {
        auto at = volumesAt(r.volumes, p);
        ASSERT_FALSE(at.empty());
        float best = std::numeric_limits<float>::infinity();
        for (const ProbeVolume* v : at)
            best = std::min(best, spacingOf(*v));
        EXPECT_LE(best, 0.2001f);
    }
}

TEST(AutoPlacement, Deterministic) {
    pb::scene::Scene s = pb::scene::loadScene("courtyard");
    AutoPlacementRequest req = adaptiveRequest(0.8f);
    req.adaptive.threads = 1;
    std::string a = volumeFileText(placeAutoVolumes(s, req).volumes);
    req.adaptive.threads = 2;
    std::string b = volumeFileText(placeAutoVolumes(s, req).volumes);
    req.adaptive.threads = 3;
    std::string c = volumeFileText(placeAutoVolumes(s, req).volumes);
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, c);
    EXPECT_NE(a.find("parent = \"auto\""), std::string::npos) << "courtyard has children:\n" << a;
}

TEST(AutoPlacement, BudgetIsRespectedAndReported) {
    pb::scene::Scene s = pb::scene::loadScene("courtyard");
    for (AutoMode mode : {AutoMode::Adaptive, AutoMode::Uniform}) {
        for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Bc6h}) {
            AutoPlacementRequest req = adaptiveRequest(0.4f);
            req.mode = mode;
            req.format = f;
            req.budgetBytes = 0.75 * 1024 * 1024;
            AutoPlacementResult r = placeAutoVolumes(s, req);
            EXPECT_LE(double(r.bytes), req.budgetBytes) << autoModeName(mode);
            EXPECT_EQ(r.bytes, memoryReport(r.volumes, f).total.stored.total());
            EXPECT_GT(r.spacing, 0.4f) << "coarsened";
            ASSERT_FALSE(r.notes.empty());
            EXPECT_NE(r.notes.back().find("--probe-budget-mib"), std::string::npos);
            // Uses the budget: at most ~2.5x below it (probe counts move in whole planes).
            EXPECT_GT(double(r.bytes), 0.4 * req.budgetBytes) << autoModeName(mode);
        }
    }
    AutoPlacementRequest tiny;
    tiny.budgetBytes = 1000.0; // less than 8 probes
    EXPECT_THROW(placeAutoVolumes(s, tiny), pb::Error);
}

TEST(AutoPlacement, DefaultStaysWithinTheDefaultUniformMemory) {
    pb::scene::Scene s = pb::scene::loadScene("courtyard");
    AutoPlacementRequest uniform;
    uniform.mode = AutoMode::Uniform;
    AutoPlacementResult u = placeAutoVolumes(s, uniform);
    ASSERT_EQ(u.volumes.size(), 1u);
    AutoPlacementResult a = placeAutoVolumes(s, AutoPlacementRequest{});
    EXPECT_LE(a.bytes, u.bytes);
    EXPECT_TRUE(a.defaultBudget);
    EXPECT_EQ(a.budgetBytes, double(u.bytes));
    EXPECT_TRUE(a.notes.empty()) << "the default budget is not news";
    // Within the same memory, surfaces get the uniform grid's resolution, but for the probe
    // plane per axis that auto's lattice adds to keep planes off the boundary surfaces
    // (AutoVolume.h, HalfCellMargin): at most one cell in n coarser.
    float finest = spacingOf(a.volumes[0]);
    for (const ProbeVolume& v : a.volumes)
        finest = std::min(finest, spacingOf(v));
    const glm::ivec3 n = u.volumes[0].counts - 1; // the uniform grid's cells per axis
    const int fewest = std::min(n.x, std::min(n.y, n.z));
    EXPECT_LE(finest, spacingOf(u.volumes[0]) * float(fewest + 1) / float(fewest) * 1.0001f);
    expectSurfacesAtFinestSpacing(s, a);
}

// Ranked free space (`bake`'s default): the placement leaves the tiles at least 5% of the
// budget - placed again into 95% of it when the placement that fills the budget leaves less
// (the rooms), unless that costs over 5% of spacing - and a placement that leaves more (the
// Cornell box) is the stand-ins' own.
TEST(AutoPlacement, RankedFreeSpaceLeavesTheTilesTheirShareOfTheBudget) {
    auto finestOf = [](const AutoPlacementResult& r) {
        float f = std::numeric_limits<float>::infinity();
        for (const ProbeVolume& v : r.volumes)
            f = std::min(f, spacingOf(v));
        return f;
    };
    for (const char* name : {"rooms", "cornell"}) {
        SCOPED_TRACE(name);
        const pb::scene::Scene s = pb::scene::loadScene(name);
        AutoPlacementRequest req;
        req.sparse = true;
        req.latticeSearch = false;
        const AutoPlacementResult standIns = placeAutoVolumes(s, req);
        req.freeSpace = FreeSpace::Ranked;
        const AutoPlacementResult ranked = placeAutoVolumes(s, req);
        EXPECT_EQ(ranked.budgetBytes, standIns.budgetBytes) << "the tiles' share is in the budget";
        const bool filled =
            double(standIns.bytes) > standIns.budgetBytes * (1 - kFreeSpaceTileShare);
        if (std::string(name) == "rooms") {
            EXPECT_TRUE(filled) << "the rooms test nothing";
        }
        if (std::string(name) == "cornell") {
            EXPECT_FALSE(filled) << "the Cornell box tests nothing";
        }
        if (filled) {
            EXPECT_LE(double(ranked.bytes), ranked.budgetBytes * (1 - kFreeSpaceTileShare));
            EXPECT_GT(finestOf(ranked), finestOf(standIns));
            EXPECT_LE(finestOf(ranked), finestOf(standIns) * 1.05f);
        } else {
            ASSERT_EQ(ranked.volumes.size(), standIns.volumes.size());
            for (std::size_t v = 0; v < ranked.volumes.size(); ++v) {
                EXPECT_EQ(ranked.volumes[v].counts, standIns.volumes[v].counts);
                EXPECT_EQ(ranked.volumes[v].center, standIns.volumes[v].center);
                EXPECT_EQ(ranked.volumes[v].halfExtents, standIns.volumes[v].halfExtents);
            }
        }
    }
}

TEST(AutoPlacement, EmptySceneAndBadOptionsAreErrors) {
    pb::scene::Scene empty = pb::test::emptyScene();
    EXPECT_THROW(placeAutoVolumes(empty, AutoPlacementRequest{}), pb::Error);
    pb::scene::Scene s = pb::scene::loadScene("cornell");
    AutoPlacementRequest r;
    r.adaptive.levels = 0;
    EXPECT_THROW(placeAutoVolumes(s, r), pb::Error);
    r.adaptive.levels = 2;
    r.adaptive.spacing = -1.0f;
    EXPECT_THROW(placeAutoVolumes(s, r), pb::Error);
}

TEST(VolumeFileWrite, RoundTripIsExact) {
    pb::scene::Scene s = pb::scene::loadScene("courtyard");
    // Any nested volumes will do: the lattice search's trial bakes would only cost time.
    AutoPlacementRequest req;
    req.latticeSearch = false;
    std::vector<ProbeVolume> vs = placeAutoVolumes(s, req).volumes;
    ProbeVolume odd; // numbers that need every digit, and a rotation
    odd.name = "odd \"quoted\"";
    odd.parent = "auto";
    odd.center = vs[0].center + glm::vec3(0.1f, 1e-7f, -0.3333333f);
    odd.halfExtents = glm::vec3(0.123456789f, 1.0f / 3.0f, 2.5f);
    odd.counts = {3, 1, 7};
    odd.edgeBlend = 0.7f;
    vs.push_back(odd);
    std::string text = volumeFileText(vs, "header line one\nline two");
    EXPECT_EQ(text.rfind("# header line one\n# line two\n", 0), 0u);
    VolumeFile back = parseVolumeToml(text, "roundtrip.toml");
    ASSERT_EQ(back.volumes.size(), vs.size());
    for (std::size_t i = 0; i < vs.size(); ++i) {
        const ProbeVolume &a = vs[i], &b = back.volumes[i];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.parent, b.parent);
        EXPECT_EQ(a.center, b.center) << a.name;
        EXPECT_EQ(a.halfExtents, b.halfExtents) << a.name;
        EXPECT_EQ(a.counts, b.counts);
        EXPECT_EQ(a.rotation, b.rotation);
        EXPECT_EQ(a.edgeBlend, b.edgeBlend);
    }
    EXPECT_EQ(volumeFileText(back.volumes, "header line one\nline two"), text);
}

TEST(AutoPlacement, LatticeSearchOnlyShiftsWithinTheBudgetAndIsDeterministic) {
    // Under a budget, auto ends with the measured lattice search (LatticeShiftSearch.h).
    const pb::scene::Scene s = pb::scene::loadScene("courtyard");
    AutoPlacementRequest uniform;
    uniform.mode = AutoMode::Uniform;
    AutoPlacementRequest r;
    r.sparse = true;
    r.budgetBytes = 0.5 * double(placeAutoVolumes(s, uniform).bytes);
    r.adaptive.threads = 1;
    const AutoPlacementResult a = placeAutoVolumes(s, r);
    ASSERT_TRUE(a.latticeSearched);
    EXPECT_LE(double(a.bytes), r.budgetBytes);
    EXPECT_GT(a.latticeShift.trials, 0);
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_LE(std::abs(a.latticeShift.cells[axis]), 0.4f + 1e-6f);
    // A shift is kept only for a clear gain; none keeps the estimate as it was.
    if (a.latticeShift.cells != glm::vec3(0.0f)) {
        EXPECT_LT(a.latticeShift.errorAfter,
                  a.latticeShift.errorBefore * (1.0 - kLatticeShiftMargin));
    } else {
        EXPECT_EQ(a.latticeShift.errorAfter, a.latticeShift.errorBefore);
    }

    // Without the search: the same volumes, unshifted.
    AutoPlacementRequest off = r;
    off.latticeSearch = false;
    const AutoPlacementResult b = placeAutoVolumes(s, off);
    EXPECT_FALSE(b.latticeSearched);
    ASSERT_EQ(a.volumes.size(), b.volumes.size());
    glm::vec3 cell(std::numeric_limits<float>::infinity());
    for (const ProbeVolume& v : b.volumes)
        cell = glm::min(cell, v.cellSize());
    for (std::size_t i = 0; i < a.volumes.size(); ++i) {
        EXPECT_EQ(a.volumes[i].counts, b.volumes[i].counts);
        EXPECT_EQ(a.volumes[i].halfExtents, b.volumes[i].halfExtents);
        EXPECT_NEAR(
            glm::length(a.volumes[i].center - (b.volumes[i].center + a.latticeShift.cells * cell)),
            0.0f, 1e-4f);
    }

    // The same placement on any thread count.
    AutoPlacementRequest two = r;
    two.adaptive.threads = 2;
    EXPECT_EQ(volumeFileText(a.volumes), volumeFileText(placeAutoVolumes(s, two).volumes));
}
