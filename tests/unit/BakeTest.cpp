// The Embree bake against analytic answers: white furnace, an emissive closed room converging
// with bounces, classification, relocation, nesting, determinism, degenerate set-ups.
#include "ProbeTestScenes.h"
#include "core/Error.h"
#include "probes/bake/Baker.h"
#include "probes/Octahedral.h"
#include "probes/store/ProbeFile.h"
#include "probes/ProbeSampler.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <string>

using namespace pb::probes;
using namespace pb::test;

namespace {

ProbeVolume volume(const std::string& name, glm::vec3 c, glm::vec3 h, glm::ivec3 n) {
    ProbeVolume v;
    v.name = name;
    v.center = c;
    v.halfExtents = h;
    v.counts = n;
    return v;
}

BakeRequest request(std::vector<ProbeVolume> vols, const pb::scene::Scene& s, int bounces = 1,
                    int rays = 128) {
    BakeRequest r;
    r.volumes = std::move(vols);
    r.scenarios = resolveScenarios({}, {}, s);
    r.settings.raysPerProbe = rays;
    r.settings.bounces = bounces;
    r.settings.format = StorageFormat::Rgba32f;
    return r;
}

// A closed room (inward faces, so the sun and sky stay outside) lit from inside by an emissive
// box and a point light; `wall` (optional) receives the walls' material index.
pb::scene::Scene litClosedRoom(int* wall = nullptr) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.2f, 0.3f, 0.5f));
    s.sun.enabled = true;
    const int walls = addMaterial(s, glm::vec3(0.7f, 0.5f, 0.3f));
    if (wall) *wall = walls;
    int lamp = addMaterial(s, glm::vec3(0.1f), glm::vec3(4.0f, 3.0f, 1.0f));
    addInstance(s, boxPrimitive({-2, 0, -2}, {2, 3, 2}, true, walls));
    addInstance(s, boxPrimitive({-0.3f, 2.5f, -0.3f}, {0.3f, 2.9f, 0.3f}, false, lamp));
    pb::scene::Light point;
    point.position = {1, 1, 1};
    point.intensity = 5.0f;
    s.lights.push_back(point);
    return s;
}

// litClosedRoom with a 1 m block of the walls' material on its floor.
pb::scene::Scene litRoomWithBlock() {
    int wall = 0;
    pb::scene::Scene s = litClosedRoom(&wall);
    addInstance(s, boxPrimitive({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}, false, wall));
    return s;
}

// Calls f(value) for every interior irradiance texel channel (RGB) of valid probes.
template <class F> void forEachIrradiance(const ProbeSet& set, int scenario, F f) {
    for (size_t v = 0; v < set.volumes.size(); ++v) {
        const ProbeVolume& vol = set.volumes[v];
        for (int p = 0; p < vol.probeCount(); ++p) {
            if (!set.states[v][size_t(p)].valid) continue;
            glm::ivec3 c = vol.probeCoords(p);
            for (int j = 0; j < kIrradianceInterior; ++j)
                for (int i = 0; i < kIrradianceInterior; ++i) {
                    const float* t = set.irradiance[size_t(scenario)][v].at(
                        c.x * kIrradianceTile + 1 + i, c.z * kIrradianceTile + 1 + j, c.y);
                    for (int ch = 0; ch < 3; ++ch)
                        f(t[ch]);
                }
        }
    }
}

} // namespace

TEST(BakeFurnace, EmptySceneUniformSkyGivesPiEverywhere) {
    pb::scene::Scene s = emptyScene(glm::vec3(1.0f));
    for (int rays : {32, 256}) {
        BakeRequest r = request({volume("v", {3, 1, -2}, {2, 1, 2}, {3, 2, 3})}, s, 2, rays);
        r.settings.format = StorageFormat::Rgba16f;
        BakeStats stats;
        ProbeSet set = bakeProbes(s, r, &stats);
        EXPECT_EQ(stats.probes, 18u);
        EXPECT_EQ(stats.invalidProbes, 0u);
        int n = 0;
        forEachIrradiance(set, 0, [&](float e) {
            EXPECT_NEAR(e, float(M_PI), 0.01f * float(M_PI));
            ++n;
        });
        EXPECT_EQ(n, 18 * 36 * 3);
        ProbeSampler sampler(set, 0);
        IrradianceSample e = sampler.sample({3.3f, 1.2f, -2.5f}, {0.3f, 1, 0}, {0, 0, 1});
        EXPECT_NEAR(e.irradiance.y, float(M_PI), 0.01f * float(M_PI));
    }
}

TEST(BakeFurnace, EmissiveRoomConvergesToAnalyticValue) {
    // Every wall emits Le and reflects rho: steady radiance Le / (1 - rho) everywhere, so
    // E = pi Le / (1 - rho). Pass b sees sum_{k<b} rho^k of it: E_b = pi Le (1 - rho^b)/(1 - rho).
    const float le = 1.0f, rho = 0.5f;
    pb::scene::Scene s = emissiveRoom(le, rho);
    float previous = 0.0f;
    const float analytic = float(M_PI) * le / (1.0f - rho);
    for (int b = 1; b <= 8; ++b) {
        ProbeSet set = bakeProbes(
            s, request({volume("room", {0, 0, 0}, {0.7f, 0.7f, 0.7f}, {3, 3, 3})}, s, b));
        double sum = 0.0;
        float lo = 1e9f, hi = -1e9f;
        int n = 0;
        forEachIrradiance(set, 0, [&](float e) {
            sum += e;
            lo = std::min(lo, e);
            hi = std::max(hi, e);
            ++n;
        });
        float mean = float(sum / n);
        float expected = float(M_PI) * le * (1.0f - std::pow(rho, float(b))) / (1.0f - rho);
        EXPECT_NEAR(mean, expected, 2e-3f * expected) << "bounces " << b;
        EXPECT_LT(hi - lo, 2e-3f * expected) << "bounces " << b;
        EXPECT_GT(mean, previous) << "not monotone at bounces " << b;
        previous = mean;
        if (b == 8) {
            EXPECT_NEAR(mean, analytic, 0.02f * analytic);
        }
    }
}

TEST(BakeClassification, ProbesInsideSingleSidedGeometryAreInvalid) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.5f));
    int m = addMaterial(s, glm::vec3(0.5f));
    // A solid block (faces outward) around the probe at x = -1.
    addInstance(s, boxPrimitive({-1.3f, -0.3f, -0.3f}, {-0.7f, 0.3f, 0.3f}, false, m));
    BakeRequest r = request({volume("v", {0, 0, 0}, {1, 0.5f, 0.5f}, {3, 1, 1})}, s);
    r.settings.relocate = false;
    BakeStats stats;
    ProbeSet set = bakeProbes(s, r, &stats);
    EXPECT_FALSE(set.states[0][0].valid);
    EXPECT_GT(set.states[0][0].backfaceRatio, 0.99f);
    EXPECT_TRUE(set.states[0][1].valid);
    EXPECT_TRUE(set.states[0][2].valid);
    EXPECT_EQ(stats.invalidProbes, 1u);

    // The same block double-sided has no inside: nothing is a back face.
    s.materials[size_t(m)].doubleSided = true;
    ProbeSet ds = bakeProbes(s, r);
    EXPECT_TRUE(ds.states[0][0].valid);
    EXPECT_EQ(ds.states[0][0].backfaceRatio, 0.0f);
}

TEST(BakeClassification, RelocationMovesProbesOutOfThinGeometry) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.5f));
    int m = addMaterial(s, glm::vec3(0.5f));
    // A small block around the middle probe (cell = 1): it can step out within 0.45 cell.
    addInstance(s, boxPrimitive({-0.1f, -0.1f, -0.1f}, {0.1f, 0.1f, 0.1f}, false, m));
    BakeRequest r = request({volume("v", {0, 0, 0}, {1, 0.5f, 0.5f}, {3, 1, 1})}, s);
    BakeStats stats;
    ProbeSet set = bakeProbes(s, r, &stats);
    const ProbeState& mid = set.states[0][1];
    EXPECT_TRUE(mid.valid);
    EXPECT_GT(glm::length(mid.offset), 0.1f);
    for (int a = 0; a < 3; ++a)
        EXPECT_LE(std::abs(mid.offset[a]), kMaxRelocation * 1.0f + 1e-6f);
    EXPECT_EQ(stats.relocatedProbes, 1u);
    EXPECT_EQ(stats.invalidProbes, 0u);
}

TEST(BakeClassification, RelocationNeverLeavesAChildVolumesBox) {
    // A room volume ending in the middle of a thin wall (the rooms' partition, issue 24): its
    // probes on that face sit inside the wall, equally near both sides. Moved to the far side
    // they would light this room with the next one's light; they must step inwards.
    pb::scene::Scene s = emptyScene(glm::vec3(0.5f));
    int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-0.025f, -2, -2}, {0.025f, 2, 2}, false, m));
    const ProbeVolume house = volume("house", {0, 0, 0}, {2.5f, 1, 1}, {3, 2, 2});
    ProbeVolume v = volume("room", {1, 0, 0}, {1, 0.5f, 0.5f}, {3, 2, 2});
    v.parent = "house";
    ProbeSet set = bakeProbes(s, request({house, v}, s));
    int onFace = 0;
    for (int p = 0; p < v.probeCount(); ++p) {
        const glm::ivec3 c = v.probeCoords(p);
        const ProbeState& st = set.states[1][size_t(p)];
        const glm::vec3 local = v.gridLocal(c) + st.offset;
        for (int a = 0; a < 3; ++a)
            EXPECT_LE(std::abs(local[a]), v.halfExtents[a] + 1e-6f) << "probe " << p;
        if (c.x != 0) continue;
        ++onFace;
        EXPECT_TRUE(st.valid) << "probe " << p;
        EXPECT_GT(st.offset.x, 0.025f) << "probe " << p << ": out of the wall, into the room";
    }
    EXPECT_EQ(onFace, 4);
}

TEST(BakeStatsPhases, SplitTheTracingTimeWithoutGapsOrOverlap) {
    // bench_bake reports where the tracing went: each part named once, none negative, and
    // together they are the tracing time.
    pb::scene::Scene s = emptyScene(glm::vec3(0.5f));
    int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-2, -1, -2}, {2, 2, 2}, true, m));
    BakeRequest r = request({volume("v", {0, 0.5f, 0}, {1.5f, 1.0f, 1.5f}, {3, 2, 3})}, s, 2, 32);
    BakeStats stats;
    bakeProbes(s, r, &stats);
    std::set<std::string> names;
    double wall = 0.0, cpu = 0.0;
    for (const BakePhase& p : stats.phases) {
        EXPECT_TRUE(names.insert(p.name).second) << p.name << " twice";
        EXPECT_GE(p.wallSeconds, 0.0);
        EXPECT_GE(p.cpuSeconds, 0.0);
        wall += p.wallSeconds;
        cpu += p.cpuSeconds;
    }
    EXPECT_EQ(names, (std::set<std::string>{"geometry", "setup", "trace", "lookup", "convolve"}));
    EXPECT_DOUBLE_EQ(wall, stats.traceSeconds);
    EXPECT_DOUBLE_EQ(cpu, stats.traceCpuSeconds);
    EXPECT_GT(stats.traceSeconds, 0.0);
}

TEST(BakeDeterminism, SameInputsGiveIdenticalBytesForAnyThreadCount) {
    const pb::scene::Scene s = litClosedRoom();
    BakeRequest r = request({volume("v", {0, 1.5f, 0}, {1.8f, 1.4f, 1.8f}, {4, 3, 4})}, s, 2, 64);
    r.settings.format = StorageFormat::Rgba16f;
    std::vector<std::uint8_t> reference;
    for (int threads : {1, 2, 3, 8}) {
        r.threads = threads;
        std::vector<std::uint8_t> bytes = serializeProbeSet(bakeProbes(s, r));
        if (reference.empty()) reference = bytes;
        EXPECT_EQ(bytes, reference) << "threads " << threads;
    }
    // Slabs (the batched, cell-sorted indirect lookups) change the order of work only: one
    // probe per slab, slabs that split the 48 probes unevenly, one slab for all.
    for (int slab : {1, 5, 48}) {
        r.threads = 2;
        r.slabProbes = slab;
        EXPECT_EQ(serializeProbeSet(bakeProbes(s, r)), reference) << "slab " << slab;
    }
    r.slabProbes = 0;
    r.settings.seed = 2;
    EXPECT_NE(serializeProbeSet(bakeProbes(s, r)), reference) << "the seed must matter";
}

// The lattice search's trial bakes skip what their sampler never reads (the SH fit, the noise
// measurement): their irradiance and visibility are the full bake's, byte for byte.
TEST(BakeDeterminism, IrradianceOnlyTrialKeepsTheIrradianceBytes) {
    const pb::scene::Scene s = litRoomWithBlock();
    BakeRequest r = request({volume("v", {0, 1.5f, 0}, {1.8f, 1.4f, 1.8f}, {4, 3, 4})}, s, 2, 64);
    r.settings.noiseTarget = 0.0f; // as the trials bake: one round
    BakeStats fullStats, trialStats;
    const ProbeSet full = bakeProbes(s, r, &fullStats);
    r.irradianceOnly = true;
    const ProbeSet trial = bakeProbes(s, r, &trialStats);
    ASSERT_EQ(trial.irradiance.size(), full.irradiance.size());
    ASSERT_GT(*std::max_element(full.irradiance[0][0].texels.begin(),
                                full.irradiance[0][0].texels.end()), 0.1f) << "a lit room";
    EXPECT_EQ(trial.irradiance[0][0].texels, full.irradiance[0][0].texels);
    EXPECT_EQ(trial.visibility[0].texels, full.visibility[0].texels);
    auto shLength = [](const ProbeSet& set) {
        double sum = 0.0;
        for (const glm::vec3& c : set.sh[0][0])
            sum += double(glm::length(c));
        return sum;
    };
    EXPECT_GT(shLength(full), 0.0);
    EXPECT_EQ(shLength(trial), 0.0) << "a trial fits no SH";
    EXPECT_GT(fullStats.noiseMean, 0.0);
    EXPECT_EQ(trialStats.noiseMean, 0.0) << "a trial measures no noise";
}

// Stored sparse, a trial keeps only the surface cells' probes and reads nothing else, so it
// traces the geometry of those alone: what it stores is the full bake's, byte for byte, for
// fewer rays.
TEST(BakeDeterminism, SparseIrradianceOnlyTrialTracesOnlyTheKeptProbes) {
    const pb::scene::Scene s = litRoomWithBlock();
    // 0.5 m cells in a 4 x 3 x 4 m room: the middle's probes touch no surface cell.
    BakeRequest r = request({volume("v", {0, 1.5f, 0}, {1.9f, 1.4f, 1.9f}, {9, 7, 9})}, s, 2, 32);
    r.settings.noiseTarget = 0.0f; // as the trials bake: one round
    r.sparse = true;
    BakeStats fullStats, trialStats;
    const ProbeSet full = bakeProbes(s, r, &fullStats);
    r.irradianceOnly = true;
    const ProbeSet trial = bakeProbes(s, r, &trialStats);
    ASSERT_LT(full.storedCount(), std::size_t(full.volumes[0].probeCount())) << "some probes dropped";
    EXPECT_EQ(trial.storedCount(), full.storedCount());
    EXPECT_EQ(trial.irradiance[0][0].texels, full.irradiance[0][0].texels);
    EXPECT_EQ(trial.visibility[0].texels, full.visibility[0].texels);
    for (std::size_t p = 0; p < full.states[0].size(); ++p) {
        const ProbeState &a = full.states[0][p], &b = trial.states[0][p];
        if (!a.stored) continue;
        EXPECT_TRUE(b.stored) << p;
        EXPECT_EQ(a.offset, b.offset) << p;
    }
    EXPECT_LT(trialStats.primaryRays, fullStats.primaryRays) << "the dropped probes' geometry is not traced";
}

// The lattice search hands each trial the scene's triangles and the sparse masks its budget
// check already marked (BakeRequest::staticTriangles, keptProbes): the same bytes as a trial
// that gathers and marks them itself. A wrong mask changes them (the mask is what the trial
// reads), and a trial carries no input hash (nothing writes or compares it).
TEST(BakeDeterminism, SparseTrialTakesTheCallersTrianglesAndMasks) {
    const pb::scene::Scene s = litRoomWithBlock();
    BakeRequest r = request({volume("v", {0, 1.5f, 0}, {1.9f, 1.4f, 1.9f}, {9, 7, 9})}, s, 2, 32);
    r.settings.noiseTarget = 0.0f;
    r.sparse = true;
    r.irradianceOnly = true;
    const ProbeSet own = bakeProbes(s, r);
    const std::vector<pb::raytrace::WorldTriangle> triangles = pb::raytrace::staticBakeTriangles(s);
    const std::vector<std::vector<std::uint8_t>> kept{sparseKeptProbes(r.volumes[0], true, triangles)};
    r.staticTriangles = &triangles;
    r.keptProbes = &kept;
    const ProbeSet handed = bakeProbes(s, r);
    EXPECT_EQ(handed.irradiance[0][0].texels, own.irradiance[0][0].texels);
    EXPECT_EQ(handed.visibility[0].texels, own.visibility[0].texels);
    EXPECT_EQ(handed.storedCount(), own.storedCount());
    EXPECT_EQ(own.inputHash, 0u) << "a trial is never written";

    const std::vector<std::vector<std::uint8_t>> all{
        std::vector<std::uint8_t>(kept[0].size(), std::uint8_t(1))};
    ASSERT_NE(all, kept) << "some probes are dropped";
    r.keptProbes = &all;
    EXPECT_GT(bakeProbes(s, r).storedCount(), own.storedCount()) << "the mask handed in is used";

    r.irradianceOnly = false;
    r.keptProbes = nullptr;
    EXPECT_NE(bakeProbes(s, r).inputHash, 0u);
}

// In RGBA32F (as the lattice search bakes) a trial keeps its texels alone: the same texels as
// the full bake's, and no stored bytes (nothing writes or uploads a trial; the reference grid's
// were about 170 MiB).
TEST(BakeDeterminism, Rgba32fTrialKeepsTexelsWithoutStoredBytes) {
    const pb::scene::Scene s = litRoomWithBlock();
    BakeRequest r = request({volume("v", {0, 1.5f, 0}, {1.9f, 1.4f, 1.9f}, {9, 7, 9})}, s, 2, 32);
    r.settings.noiseTarget = 0.0f;
    r.settings.format = StorageFormat::Rgba32f;
    r.sparse = true;
    const ProbeSet full = bakeProbes(s, r);
    r.irradianceOnly = true;
    const ProbeSet trial = bakeProbes(s, r);
    ASSERT_FALSE(full.irradiance[0][0].stored.empty());
    EXPECT_EQ(trial.irradiance[0][0].texels, full.irradiance[0][0].texels);
    EXPECT_EQ(trial.visibility[0].texels, full.visibility[0].texels);
    EXPECT_TRUE(trial.irradiance[0][0].stored.empty());
    EXPECT_TRUE(trial.visibility[0].stored.empty());
}

TEST(BakeNesting, ChildRingTakesTheParentsIrradiance) {
    pb::scene::Scene s = emptyScene(glm::vec3(0.3f));
    s.sun.enabled = true;
    int m = addMaterial(s, glm::vec3(0.6f));
    addInstance(s, boxPrimitive({-4, -0.2f, -4}, {4, 0.0f, 4}, false, m)); // a slab floor
    ProbeVolume parent = volume("world", {0, 1.5f, 0}, {3, 1.4f, 3}, {4, 3, 4});
    ProbeVolume child = volume("room", {0.5f, 1.0f, 0.5f}, {1, 0.8f, 1}, {4, 3, 4});
    child.parent = "world";
    ProbeSet set = bakeProbes(s, request({parent, child}, s, 2, 96));
    ProbeSampler sampler(set, 0);
    SampleOptions atProbe; // as NestingBlend looks the parent up: no fade, no surface bias
    atProbe.edgeFade = false;
    atProbe.surfaceBias = false;
    int ring = 0, inner = 0;
    for (int p = 0; p < child.probeCount(); ++p) {
        glm::ivec3 c = child.probeCoords(p);
        bool onRing = c.x == 0 || c.y == 0 || c.z == 0 || c.x == 3 || c.y == 2 || c.z == 3;
        glm::vec3 pos = child.toWorld(child.gridLocal(c) + set.states[1][size_t(p)].offset);
        glm::vec3 dir = octTexelDirection(2, 3, kIrradianceInterior);
        float mine =
            set.irradiance[0][1].at(c.x * kIrradianceTile + 3, c.z * kIrradianceTile + 4, c.y)[0];
        float parents = sampler.sampleVolume(0, pos, dir, dir, atProbe).irradiance.x;
        ASSERT_EQ(set.states[1][size_t(p)].offset, glm::vec3(0.0f)) << "no probe near the floor";
        if (onRing) {
            EXPECT_NEAR(mine, parents, 1e-4f * parents + 1e-6f) << "ring probe " << p;
            ++ring;
        } else {
            ++inner;
        }
    }
    EXPECT_EQ(ring, 48 - 4);
    EXPECT_EQ(inner, 4);
}

TEST(BakeEdgeCases, VolumeOutsideTheSceneSeesOnlySky) {
    pb::scene::Scene s = emissiveRoom(1.0f, 0.5f);
    s.sky.radiance = glm::vec3(0.25f);
    ProbeSet set = bakeProbes(s, request({volume("far", {100, 0, 0}, {1, 1, 1}, {2, 2, 2})}, s));
    forEachIrradiance(set, 0, [&](float e) { EXPECT_NEAR(e, 0.25f * float(M_PI), 1e-4f); });
}

TEST(BakeEdgeCases, DynamicAndInvisibleGeometryIsNotBaked) {
    pb::scene::Scene s = emptyScene(glm::vec3(1.0f));
    int m = addMaterial(s, glm::vec3(0.0f));
    addInstance(s, boxPrimitive(glm::vec3(-1), glm::vec3(1), true, m), glm::mat4(1.0f), true);
    int glass = addMaterial(s, glm::vec3(0.0f));
    s.materials[size_t(glass)].alphaMode = pb::scene::AlphaMode::Blend;
    s.materials[size_t(glass)].baseColor.a = 0.0f;
    addInstance(s, boxPrimitive(glm::vec3(-1.5f), glm::vec3(1.5f), true, glass));
    ProbeSet set =
        bakeProbes(s, request({volume("v", {0, 0, 0}, {0.5f, 0.5f, 0.5f}, {2, 2, 2})}, s));
    forEachIrradiance(set, 0, [&](float e) { EXPECT_NEAR(e, float(M_PI), 1e-4f); });
}

TEST(BakeEdgeCases, BadRequestsAreClearErrors) {
    pb::scene::Scene s = emptyScene();
    EXPECT_THROW(bakeProbes(s, request({}, s)), pb::Error);
    BakeRequest r = request({volume("v", {0, 0, 0}, {1, 1, 1}, {0, 2, 2})}, s);
    EXPECT_THROW(bakeProbes(s, r), pb::Error);
    r = request({volume("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2})}, s);
    r.settings.bounces = -1; // 0 is legal: until converged
    EXPECT_THROW(bakeProbes(s, r), pb::Error);
    r.settings.bounces = 65;
    EXPECT_THROW(bakeProbes(s, r), pb::Error);
    r.settings.bounces = 1;
    r.settings.raysPerProbe = 0;
    EXPECT_THROW(bakeProbes(s, r), pb::Error);
    r.settings.raysPerProbe = 1; // tiny but legal: still finite, still pi
    ProbeSet set = bakeProbes(s, r);
    forEachIrradiance(set, 0, [&](float e) { EXPECT_NEAR(e, float(M_PI), 1e-4f); });
}

TEST(BakeScenarios, EachScenarioGetsItsOwnIrradiance) {
    pb::scene::Scene s = emptyScene(glm::vec3(1.0f));
    BakeRequest r = request({volume("v", {0, 0, 0}, {1, 1, 1}, {2, 2, 2})}, s);
    r.scenarios = resolveScenarios({"day", "night"}, {}, s);
    ProbeSet set = bakeProbes(s, r);
    ASSERT_EQ(set.irradiance.size(), 2u);
    EXPECT_EQ(set.findScenario("night"), 1);
    forEachIrradiance(set, 1, [&](float e) { EXPECT_LT(e, 0.05f); });
    forEachIrradiance(set, 0, [&](float e) { EXPECT_NEAR(e, float(M_PI), 1e-4f); });
}

TEST(BakeHash, ChangesWithEveryInput) {
    pb::scene::Scene s = emissiveRoom(1.0f, 0.5f);
    BakeRequest r = request({volume("v", {0, 0, 0}, {0.5f, 0.5f, 0.5f}, {2, 2, 2})}, s);
    const std::uint64_t h = bakeInputHash(s, r);
    EXPECT_EQ(bakeInputHash(s, r), h);
    BakeRequest t = r;
    t.threads = 7;
    EXPECT_EQ(bakeInputHash(s, t), h) << "threads never change the result";
    auto differs = [&](auto mutate) {
        pb::scene::Scene s2 = s;
        BakeRequest r2 = r;
        mutate(s2, r2);
        return bakeInputHash(s2, r2) != h;
    };
    EXPECT_TRUE(differs([](auto& sc, auto&) { sc.primitives[0].positions[0].x += 1e-3f; }));
    EXPECT_TRUE(differs([](auto& sc, auto&) { sc.materials[1].baseColor.r = 0.4f; }));
    EXPECT_TRUE(differs([](auto& sc, auto&) { sc.lights.emplace_back(); }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.volumes[0].counts.x = 3; }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.settings.raysPerProbe = 64; }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.settings.bounces = 3; }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.settings.seed = 9; }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.settings.format = StorageFormat::Bc6h; }));
    EXPECT_TRUE(differs([](auto&, auto& rq) { rq.scenarios[0].sky.radiance.x = 2.0f; }));
}
