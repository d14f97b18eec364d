// Lookups in free space from a sparse set (issue 18): sparse storage keeps the surface cells'
// probes and a coarse lattice through the air whole; the other valid probes are read as their
// nearest stored one (the default, probes/AbsentProbeFill.h) or keep their irradiance without
// visibility (FreeSpace::Irradiance, ProbeState::irradianceOnly). Every point inside a volume
// must get a lookup close to the dense set's, while lookups whose corners are all stored stay
// bit for bit.
#include "DenseAndSparseBake.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeSampler.h"
#include "probes/bake/Baker.h"
#include "probes/bake/MidAirSamples.h"
#include "raytrace/RayScene.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::probes;

namespace {

float luminance(const glm::vec3& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

using pb::test::bakeDenseAndSparse;
using pb::test::DenseAndSparse;

const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

struct MidAirError {
    int lookups = 0, changed = 0, unlit = 0;
    // Relative luminance error of the lookups that differ from the dense one (below).
    float mean = 0.0f, p90 = 0.0f, worst = 0.0f;
    // Of those, the ones more than 15% outside the dense light within the stand-ins' reach
    // (below), and by how much the worst one lies outside it (relative, as the error; <= 0:
    // inside).
    int outsideReach = 0;
    float worstBeyondReach = -1.0f;
};

// How far from a point the probes its lookup reads can lie, in cells per axis: a corner of its
// cell is at most one cell away, and a stand-in at most one cell per axis from the corner it
// replaces (the nearest stored probe; the step-2 lattice has one that near).
constexpr int kStandInReachCells = 2;

// The free-space points on the grid of cell steps around `p` within that reach (p included):
// where the dense set's own light is compared with what the sparse lookup read.
std::vector<glm::vec3> freeSpaceNeighbours(const pb::raytrace::RayScene& rs, const ProbeVolume& v,
                                           const glm::vec3& p) {
    std::vector<glm::vec3> out{p};
    const int r = kStandInReachCells;
    for (int dz = -r; dz <= r; ++dz)
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                const glm::vec3 q = p + v.rotation * (glm::vec3(dx, dy, dz) * v.cellSize());
                if ((dx || dy || dz) && !insideGeometry(rs, q, v.minCellSize())) out.push_back(q);
            }
    return out;
}

// The dense set's luminance range over those points (the lookups with weight).
struct Range {
    float lo, hi;
};
Range denseRange(const ProbeSampler& dense, const std::vector<glm::vec3>& points,
                 const glm::vec3& n) {
    Range r{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    for (const glm::vec3& q : points) {
        const IrradianceSample d = dense.sample(q, n, n, midAirLookup());
        if (!(d.weight > 0.0f)) continue;
        r.lo = std::min(r.lo, luminance(d.irradiance));
        r.hi = std::max(r.hi, luminance(d.irradiance));
    }
    return r;
}

MidAirError compareMidAir(const DenseAndSparse& b, int points) {
    const pb::raytrace::RayScene rs(b.scene);
    const ProbeSampler dense(b.dense, 0), sparse(b.sparse, 0);
    struct Pair {
        float dense, sparse;
        Range reach; // the dense light within the stand-ins' reach
    };
    std::vector<Pair> filled;
    MidAirError e;
    double total = 0.0;
    for (const glm::vec3& p :
         midAirSamples(rs, b.dense.volumes, points, b.dense.volumes[0].minCellSize())) {
        std::vector<glm::vec3> around; // computed for the first lookup that needs it
        for (const glm::vec3& n : kAxes) {
            const IrradianceSample d = dense.sample(p, n, n, midAirLookup()),
                                   s = sparse.sample(p, n, n, midAirLookup());
            ++e.lookups;
            total += luminance(d.irradiance);
            if (d.weight > 0.0f && !(s.weight > 0.0f)) ++e.unlit;
            // A lookup whose 8 corners are all stored (or inside geometry in both) is the dense
            // lookup bit for bit; the others read stand-ins, irradiance-only corners or fewer
            // probes.
            if (s.filled == 0 && s.irradianceOnly == 0 && s.probes == d.probes) {
                EXPECT_EQ(s.irradiance, d.irradiance)
                    << "all corners stored, yet not the dense lookup";
                continue;
            }
            if (around.empty()) around = freeSpaceNeighbours(rs, b.dense.volumes[0], p);
            filled.push_back(
                {luminance(d.irradiance), luminance(s.irradiance), denseRange(dense, around, n)});
        }
    }
    const float floor = 0.1f * float(total / std::max(e.lookups, 1));
    std::vector<float> rel;
    double sum = 0.0;
    for (const Pair& q : filled) {
        const float scale = std::max(q.dense, floor);
        rel.push_back(std::abs(q.sparse - q.dense) / scale);
        sum += rel.back();
        const float beyond = std::max(q.reach.lo - q.sparse, q.sparse - q.reach.hi) / scale;
        e.worstBeyondReach = std::max(e.worstBeyondReach, beyond);
        if (beyond > 0.15f) ++e.outsideReach;
    }
    e.changed = int(rel.size());
    if (rel.empty()) return e;
    std::sort(rel.begin(), rel.end());
    e.mean = float(sum / double(rel.size()));
    e.p90 = rel[rel.size() * 9 / 10];
    e.worst = rel.back();
    return e;
}

// Bakes `scene` dense and sparse with `freeSpace`, compares them at 500 mid-air points and
// prints the figures; every point must be lit and read something other than stored probes
// often enough for the comparison to mean anything.
MidAirError measureMidAir(const char* scene, FreeSpace freeSpace) {
    const DenseAndSparse b = bakeDenseAndSparse(scene, 1500, freeSpace);
    EXPECT_LT(b.sparse.storedCount(), b.sparse.probeCount()) << "nothing absent: vacuous";
    const MidAirError e = compareMidAir(b, 500);
    std::printf("[ mid-air ] %s, %s: %d of %zu probes stored; %d lookups, %d differ from the "
                "dense one: relative luminance error mean %.4f, p90 %.4f, worst %.4f; %d unlit; "
                "worst beyond the dense light within reach %.4f\n",
                scene, freeSpace == FreeSpace::Irradiance ? "irradiance-only" : "stand-ins",
                int(b.sparse.storedCount()), b.sparse.probeCount(), e.lookups, e.changed, e.mean,
                e.p90, e.worst, e.unlit, e.worstBeyondReach);
    EXPECT_EQ(e.unlit, 0) << "a point the dense set lights got no lookup";
    EXPECT_GT(e.changed, e.lookups / 10)
        << "too few lookups read an absent probe's stand-in or irradiance: vacuous";
    return e;
}

} // namespace

class MidAir : public testing::TestWithParam<const char*> {};

// The default storage (stand-ins; studies/findings/mid-air-options.md, "Mid-air options"): every point gets a
// lookup; the lookups that differ from the dense one at all are within 15% of it on average;
// and none lies more than 15% outside the light the dense set itself gives within the
// stand-ins' reach of the point (two cells per axis). Not within 15% of the dense lookup at
// the point itself everywhere: under the Cornell box's ceiling light and in the rooms' doorway
// the light changes by 2x within a cell, and a stand-in one cell nearer the light reads that
// much brighter (studies/results/2026-11-25-mid-air-worst.md).
TEST_P(MidAir, StandInsLightEveryPointWithin15PercentOfTheDenseLightWithinReach) {
    const MidAirError e = measureMidAir(GetParam(), FreeSpace::StandIns);
    EXPECT_LE(e.mean, 0.15f);
    EXPECT_EQ(e.outsideReach, 0)
        << "a lookup is off by more than 15% beyond the dense light within reach (worst "
        << e.worstBeyondReach << ")";
}

// Issue 18's target with the probes left out keeping their irradiance (`bake
// --free-space-irradiance`): every lookup that differs from the dense one at all is within 15%
// of it, under the Cornell light and in the rooms' doorway too.
TEST_P(MidAir, IrradianceOnlyProbesLightEveryPointWithin15PercentOfTheDenseLookup) {
    const MidAirError e = measureMidAir(GetParam(), FreeSpace::Irradiance);
    EXPECT_LE(e.worst, 0.15f) << "a mid-air lookup is more than 15% off the dense one";
    EXPECT_EQ(e.outsideReach, 0)
        << "a lookup is off by more than 15% beyond the dense light within reach (worst "
        << e.worstBeyondReach << ")";
}

// Issue 18's target for the default bake (`bake --volumes auto`, FreeSpace::Ranked): the
// left-out probes whose stand-ins are furthest off keep their irradiance within the placement's
// budget, and every mid-air lookup is then within 15% of the dense bake of the same volumes.
TEST_P(MidAir, TheDefaultBakeLightsEveryPointWithin15PercentOfTheDenseBake) {
    double budget = 0.0;
    const DenseAndSparse b = pb::test::bakeDefaultDenseAndSparse(GetParam(), budget);
    ASSERT_EQ(b.dense.volumes.size(), 1u) << "compareMidAir reads one volume";
    ASSERT_GT(budget, 0.0);
    const MemoryReport m = memoryReport(b.sparse);
    EXPECT_LE(double(m.total.storedTotal()), budget) << "the tiles broke the budget";
    EXPECT_GT(m.total.irradianceOnlyProbes, 0u) << "no tile chosen: vacuous";
    const MidAirError e = compareMidAir(b, 500);
    std::printf("[ mid-air ] %s, default bake: %zu of %zu probes stored, %zu irradiance-only, "
                "%.0f of %.0f KiB; %d lookups, %d differ from the dense one: mean %.4f, p90 "
                "%.4f, worst %.4f; %d unlit\n",
                GetParam(), b.sparse.storedCount(), b.sparse.probeCount(),
                m.total.irradianceOnlyProbes, double(m.total.storedTotal()) / 1024, budget / 1024,
                e.lookups, e.changed, e.mean, e.p90, e.worst, e.unlit);
    EXPECT_EQ(e.unlit, 0) << "a point the dense set lights got no lookup";
    EXPECT_GT(e.changed, e.lookups / 20) << "too few lookups read a left-out probe: vacuous";
    EXPECT_LE(e.worst, 0.15f) << "a mid-air lookup is more than 15% off the dense one";
}

INSTANTIATE_TEST_SUITE_P(Builtin, MidAir, testing::Values("cornell", "rooms", "courtyard"));
