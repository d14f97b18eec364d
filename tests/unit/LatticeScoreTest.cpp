// The lattice measure (issue 24): a residual that repeats with the probe spacing scores far
// above 1, noise and slow trends score about 1, and the score follows the frequency asked
// for; floor lines lie on flat upward surfaces only, stay on them, and are the same for the
// same seed.
#include "ProbeTestScenes.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "studies/common/LatticeScore.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pb;
using namespace pb::probes;
using namespace pb::test;

namespace {
constexpr float kStep = 0.125f, kSpacing = 1.0f; // 8 samples per cell
constexpr int kSamples = 64;

std::vector<double> latticeScoreNoise(std::uint64_t seed, double amplitude) {
    std::vector<double> r(kSamples);
    for (double& v : r)
        v = amplitude * (uniformFloat(seed) - 0.5);
    return r;
}

// A 6 x 6 m floor at y = 0, centred on the origin, facing up.
void addFloor(scene::Scene& s, int material) {
    scene::Primitive floor;
    floor.material = material;
    addQuad(floor, {-3, 0, -3}, {6, 0, 0}, {0, 0, 6}, {0, 1, 0});
    addInstance(s, floor);
}
} // namespace

TEST(LatticeScore, ARippleAtTheSpacingStandsOutOfNoiseAndTrend) {
    std::vector<double> ripple = latticeScoreNoise(3, 0.02);
    for (int i = 0; i < kSamples; ++i) // rings under the probes + a slow gradient
        ripple[size_t(i)] += 0.1 * std::cos(2 * M_PI * i * kStep / kSpacing) + 0.01 * i;
    const double rippled = studies::latticeScore(ripple, kStep, 1.0f / kSpacing);
    EXPECT_GT(rippled, 20.0);
    // The same ripple scored at another spacing's frequency is not a peak there.
    EXPECT_LT(studies::latticeScore(ripple, kStep, 1.0f / (2.2f * kSpacing)), 0.5 * rippled);

    // Noise alone, and noise on a trend: about 1 on average over many lines (a single line of
    // noise scatters; the bench reports medians).
    double sum = 0.0;
    for (std::uint64_t s = 1; s <= 200; ++s) {
        std::vector<double> r = latticeScoreNoise(s * 7919, 0.1);
        for (int i = 0; i < kSamples; ++i)
            r[size_t(i)] += 0.05 * i;
        sum += studies::latticeScore(r, kStep, 1.0f / kSpacing) / 200.0;
    }
    EXPECT_GT(sum, 0.5);
    EXPECT_LT(sum, 2.0);
    // A flat residual has no power anywhere: 0, not a division by zero.
    EXPECT_EQ(studies::latticeScore(std::vector<double>(kSamples, 0.25), kStep, 1.0f), 0.0);
}

TEST(LatticeScore, FloorLinesStayOnFlatUpwardSurfaces) {
    // A 6 x 6 m floor at y = 0 with a 1 m step up (a 2 x 6 m platform at x > 1, y = 1) and a
    // sloped ramp nowhere: lines must lie at y = 0 or y = 1 and never cross the step.
    scene::Scene s = emptyScene();
    const int m = addMaterial(s, glm::vec3(0.5f));
    addFloor(s, m);
    addInstance(s, boxPrimitive({1, 0, -3}, {3, 1, 3}, false, m));
    const pb::raytrace::RayScene rs(s);
    const std::vector<studies::FloorLine> lines = studies::findFloorLines(rs, 20, 16, 0.1f);
    ASSERT_GE(lines.size(), 10u);
    for (const studies::FloorLine& l : lines) {
        const float y = l.start.y;
        EXPECT_TRUE(std::fabs(y) < 0.01f || std::fabs(y - 1.0f) < 0.01f) << y;
        for (int i = 0; i < l.samples; ++i) {
            const glm::vec3 p = l.point(i);
            // The same surface all along: below x = 1 on the floor, above it on the platform.
            if (std::fabs(y) < 0.01f) EXPECT_LT(p.x, 1.0f + 1e-3f);
            else EXPECT_GE(p.x, 1.0f - 1e-3f);
            EXPECT_LE(std::fabs(p.x), 3.0f + 1e-3f);
            EXPECT_LE(std::fabs(p.z), 3.0f + 1e-3f);
        }
    }
    // Deterministic for a seed.
    const std::vector<studies::FloorLine> again = studies::findFloorLines(rs, 20, 16, 0.1f);
    ASSERT_EQ(again.size(), lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i)
        EXPECT_EQ(again[i].start, lines[i].start);
    // No upward surface at all (a wall alone): no lines.
    scene::Scene wall = emptyScene();
    scene::Primitive w;
    w.material = addMaterial(wall, glm::vec3(0.5f));
    addQuad(w, {0, 0, -1}, {0, 2, 0}, {0, 0, 2}, {1, 0, 0});
    addInstance(wall, w);
    EXPECT_TRUE(studies::findFloorLines(pb::raytrace::RayScene(wall), 5, 16, 0.1f).empty());
}

TEST(LatticeScore, FloorLinesDoNotRunInsideAWallWhoseTopIsInTheCeiling) {
    // The rooms' build: a 6 x 6 m floor, a wall box standing on it (|x| < 0.5, up to y = 2) and
    // a ceiling box that holds the wall's top. From a floor point inside the wall, the first
    // thing straight up is the ceiling's underside, so only the other directions show that the
    // point is inside a solid.
    scene::Scene s = emptyScene();
    const int m = addMaterial(s, glm::vec3(0.5f));
    addFloor(s, m);
    addInstance(s, boxPrimitive({-0.5f, -0.2f, -3}, {0.5f, 2.0f, 3}, false, m));
    addInstance(s, boxPrimitive({-3, 1.9f, -3}, {3, 2.1f, 3}, false, m));
    const pb::raytrace::RayScene rs(s);
    const std::vector<studies::FloorLine> lines = studies::findFloorLines(rs, 40, 8, 0.1f);
    ASSERT_GE(lines.size(), 20u);
    for (const studies::FloorLine& l : lines)
        for (int i = 0; i < l.samples; ++i)
            EXPECT_GT(std::fabs(l.point(i).x), 0.5f - 1e-3f) << "inside the wall at x "
                                                              << l.point(i).x;
}

TEST(LatticeScore, ADoubleSidedFloorWoundDownwardIsAFloorASingleSidedOneIsNot) {
    // Sponza's court floor: its triangles face down, its material is double-sided, so it is
    // rendered from above. Wound the same way but single-sided it is a ceiling's underside.
    for (bool doubleSided : {true, false}) {
        scene::Scene s = emptyScene();
        const int m = addMaterial(s, glm::vec3(0.5f));
        s.materials[size_t(m)].doubleSided = doubleSided;
        scene::Primitive floor;
        floor.material = m;
        addQuad(floor, {-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, {0, -1, 0});
        addInstance(s, floor);
        // A post in a corner gives the scene height (starts are drawn within its bounds).
        addInstance(
            s, boxPrimitive({2.5f, 0, 2.5f}, {3, 1, 3}, false, addMaterial(s, glm::vec3(0.5f))));
        const pb::raytrace::RayScene rs(s);
        const std::vector<studies::FloorLine> lines = studies::findFloorLines(rs, 10, 16, 0.1f);
        if (!doubleSided) {
            EXPECT_TRUE(lines.empty());
            continue;
        }
        ASSERT_GE(lines.size(), 5u);
        for (const studies::FloorLine& l : lines)
            EXPECT_LT(std::fabs(l.start.y), 0.01f);
    }
}
