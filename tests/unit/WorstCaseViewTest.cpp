// Coverage of a view (pixels needing GI) and the worst-case view search: analytic cases on a
// floor half inside a volume, sky and left-out volumes, overlap counting, and the search
// reaching full coverage on every built-in scene with its auto volume.
#include "unit/ProbeTestScenes.h"

#include "core/Error.h"
#include "probes/placement/AutoVolume.h"
#include "scene/SceneLoader.h"
#include "views/WorstCaseView.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

probes::ProbeVolume worstCaseViewBox(const std::string& name, glm::vec3 lo, glm::vec3 hi) {
    probes::ProbeVolume v;
    v.name = name;
    v.center = 0.5f * (lo + hi);
    v.halfExtents = 0.5f * (hi - lo);
    v.counts = glm::ivec3(2);
    return v;
}

// A 20 x 20 floor at y = 0, single-sided facing up.
scene::Scene worstCaseViewFloorScene() {
    scene::Scene s = emptyScene();
    int m = addMaterial(s, glm::vec3(0.5f));
    scene::Primitive p;
    p.material = m;
    addQuad(p, {-10, 0, -10}, {20, 0, 0}, {0, 0, 20}, {0, 1, 0});
    addInstance(s, std::move(p));
    return s;
}

// Looking straight down at the origin from 2 m: the view's right is -X (RenderView's basis
// for a vertical camera: up = +Z), so the volume over x < 0 covers exactly the right half.
scene::View worstCaseViewDownView() {
    scene::View v;
    v.name = "down";
    v.position = {0, 2, 0};
    v.target = {0, 0, 0};
    v.fovYDegrees = 60;
    return v;
}

TEST(Coverage, HalfTheFloorInsideAVolumeIsHalfThePixels) {
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("left", {-10, -1, -10}, {0, 1, 10}));
    const views::Coverage c = views::measureCoverage(s, set, worstCaseViewDownView(), 64, 36);
    EXPECT_EQ(c.width, 64);
    EXPECT_DOUBLE_EQ(c.fraction, 0.5); // pixel centres never lie on x = 0 for an even width
    EXPECT_EQ(c.maxOverlap, 1);
    EXPECT_DOUBLE_EQ(c.meanOverlap, 1.0);
    EXPECT_GT(c.meanDistance, 2.0); // slanted rays are longer than the 2 m straight down
    EXPECT_LT(c.meanDistance, 2.0 / std::cos(glm::radians(45.0)));
}

TEST(Coverage, NestedVolumesCountAsOverlapAndLeftOutOnesDoNot) {
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("all", {-10, -1, -10}, {10, 1, 10}));
    set.volumes.push_back(worstCaseViewBox("left", {-10, -1, -10}, {0, 1, 10}));
    const views::Coverage both =
        views::CoverageTester(s, set).measure(worstCaseViewDownView(), 64, 36);
    EXPECT_DOUBLE_EQ(both.fraction, 1.0);
    EXPECT_EQ(both.maxOverlap, 2);
    EXPECT_DOUBLE_EQ(both.meanOverlap, 1.5); // half the pixels in two volumes

    const views::Coverage leftOnly =
        views::CoverageTester(s, set, {false, true}).measure(worstCaseViewDownView(), 64, 36);
    EXPECT_DOUBLE_EQ(leftOnly.fraction, 0.5);
    EXPECT_EQ(leftOnly.maxOverlap, 1);
    EXPECT_THROW(views::CoverageTester(s, set, {true}), Error); // flags for 1 of 2 volumes
}

TEST(Coverage, SkyAndGeometryOutsideEveryVolumeNeedNoGi) {
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("all", {-10, -1, -10}, {10, 1, 10}));
    scene::View up = worstCaseViewDownView();
    up.target = {0, 4, 0};
    EXPECT_DOUBLE_EQ(views::measureCoverage(s, set, up, 32, 18).fraction, 0.0);

    probes::ProbeSet far;
    far.volumes.push_back(worstCaseViewBox("elsewhere", {50, -1, 50}, {60, 1, 60}));
    EXPECT_DOUBLE_EQ(views::measureCoverage(s, far, worstCaseViewDownView(), 32, 18).fraction, 0.0);
}

TEST(Coverage, ParallelAndSerialMeasurementsAgree) {
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("left", {-10, -1, -10}, {0, 1, 10}));
    scene::View v = worstCaseViewDownView();
    v.target = {1, 0, 0.5f}; // oblique: nothing symmetric to hide a row mix-up
    const views::CoverageTester t(s, set);
    const views::Coverage a = t.measure(v, 50, 30), b = t.measureSerial(v, 50, 30);
    EXPECT_DOUBLE_EQ(a.fraction, b.fraction);
    EXPECT_DOUBLE_EQ(a.meanDistance, b.meanDistance);
    EXPECT_GT(a.fraction, 0.0);
    EXPECT_LT(a.fraction, 1.0);
}

TEST(WorstCaseView, FindsFullCoverageWhereTheStartingViewsDoNot) {
    // The floor only half inside the volume and open sky above: most poses see sky or the
    // uncovered half; the search must find one looking down into the covered half.
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("left", {-10, -1, -10}, {0, 3, 10}));
    const views::WorstCase wc = views::findWorstCaseView(s, set, 160, 90);
    EXPECT_DOUBLE_EQ(wc.coverage.fraction, 1.0);
    EXPECT_EQ(wc.coverage.width, 160);
    EXPECT_GT(wc.candidates, 100);
    EXPECT_TRUE(set.volumes[0].contains(wc.view.position));
    // Deterministic: the same search gives the same camera.
    const views::WorstCase again = views::findWorstCaseView(s, set, 160, 90);
    EXPECT_EQ(again.view.position, wc.view.position);
    EXPECT_EQ(again.view.target, wc.view.target);
}

TEST(WorstCaseView, ReachesFullCoverageOnEveryBuiltinScene) {
    for (const char* name : {"cornell", "rooms", "courtyard"}) {
        SCOPED_TRACE(name);
        const scene::Scene s = scene::loadScene(name, {});
        probes::ProbeSet set;
        set.volumes.push_back(probes::fitAutoVolume(s.staticWorldBounds(), 0.0f).volume);
        const views::WorstCase wc = views::findWorstCaseView(s, set, 320, 180);
        EXPECT_DOUBLE_EQ(wc.coverage.fraction, 1.0);
        // The benchmark view is a real view, not a camera against a wall.
        EXPECT_GT(wc.coverage.meanDistance, 0.05 * glm::length(s.staticWorldBounds().size()));
    }
}

// Issue 18: dynamic objects are in the GBuffer and need GI like any pixel, so the primary rays
// see them (a box hiding part of the floor: its pixels count as dynamic, the floor behind it
// does not), and on a scene with dynamic objects the search picks a full view that shows them.
TEST(Coverage, DynamicObjectsAreSeenAndCounted) {
    scene::Scene s = worstCaseViewFloorScene();
    const int m = addMaterial(s, glm::vec3(0.5f));
    addInstance(s, boxPrimitive({-0.5f, 0.5f, -0.5f}, {0.5f, 1.0f, 0.5f}, false, m));
    probes::ProbeSet set;
    set.volumes.push_back(worstCaseViewBox("all", {-10, -1, -10}, {10, 3, 10}));
    const views::Coverage still = views::measureCoverage(s, set, worstCaseViewDownView(), 64, 36);
    EXPECT_DOUBLE_EQ(still.dynamicFraction, 0.0);
    s.instances.back().dynamic = true;
    const views::Coverage moving = views::measureCoverage(s, set, worstCaseViewDownView(), 64, 36);
    EXPECT_GT(moving.dynamicFraction, 0.05);
    EXPECT_DOUBLE_EQ(moving.fraction, 1.0);
    // The box is nearer than the floor: the mean distance drops when it is seen.
    EXPECT_LT(moving.meanDistance, views::measureCoverage(worstCaseViewFloorScene(), set,
                                                          worstCaseViewDownView(), 64, 36)
                                       .meanDistance);
}

TEST(WorstCaseView, ShowsTheDynamicObjectsOfASceneThatHasThem) {
    const scene::Scene s = scene::loadScene("rooms_dynamic", {});
    probes::ProbeSet set;
    set.volumes.push_back(probes::fitAutoVolume(s.staticWorldBounds(), 0.0f).volume);
    const views::WorstCase wc = views::findWorstCaseView(s, set, 320, 180);
    EXPECT_DOUBLE_EQ(wc.coverage.fraction, 1.0);
    EXPECT_GT(wc.coverage.dynamicFraction, 0.01) << "the worst-case view shows no dynamic object";
}

TEST(WorstCaseView, NoVolumeIsAnError) {
    const scene::Scene s = worstCaseViewFloorScene();
    probes::ProbeSet set;
    EXPECT_THROW(views::findWorstCaseView(s, set, 32, 18), Error);
    set.volumes.push_back(worstCaseViewBox("left", {-10, -1, -10}, {0, 1, 10}));
    EXPECT_THROW(views::findWorstCaseView(views::CoverageTester(s, set, {false}), 32, 18), Error);
}

} // namespace
} // namespace pb::test
