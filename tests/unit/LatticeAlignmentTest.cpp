// How much surface lies on a probe plane (LatticeAlignment.h), and that auto placement keeps
// boundary walls off its probe planes where the naive uniform fit puts them on.
#include "probes/placement/LatticeAlignment.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/store/MemoryReport.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

// A 1 x 1 wall at x = `x` facing `normal`'s way (two triangles).
std::vector<pb::raytrace::WorldTriangle> wallAt(float x, glm::vec3 normal = {1, 0, 0}) {
    const glm::vec3 a{x, 0.2f, 0.2f}, b{x, 1.2f, 0.2f}, c{x, 1.2f, 1.2f}, d{x, 0.2f, 1.2f};
    return {{a, b, c, normal, false}, {a, c, d, normal, false}};
}

// Cells of 1 along every axis over [0, 4]^3.
ProbeVolume unitGrid() {
    ProbeVolume v;
    v.name = "grid";
    v.center = glm::vec3(2.0f);
    v.halfExtents = glm::vec3(2.0f);
    v.counts = glm::ivec3(5);
    return v;
}

} // namespace

TEST(LatticeAlignment, AWallOnAProbePlaneCountsAndOneMidCellDoesNot) {
    const ProbeVolume v = unitGrid();
    EXPECT_FLOAT_EQ(surfaceOnProbePlanes(v, wallAt(2.0f)), 1.0f);
    EXPECT_FLOAT_EQ(surfaceOnProbePlanes(v, wallAt(2.5f)), 0.0f);
    // Linearly less within kOnPlaneCells of a plane; nothing beyond it.
    EXPECT_NEAR(surfaceOnProbePlanes(v, wallAt(2.05f)), 1.0f - 0.05f / kOnPlaneCells, 1e-4f);
    EXPECT_FLOAT_EQ(surfaceOnProbePlanes(v, wallAt(2.0f + kOnPlaneCells + 0.01f)), 0.0f);
    // A slanted surface lies on no plane; the share is by area over the surface in the volume.
    std::vector<pb::raytrace::WorldTriangle> mixed = wallAt(1.0f);
    for (pb::raytrace::WorldTriangle t : wallAt(2.5f))
        mixed.push_back(t);
    EXPECT_NEAR(surfaceOnProbePlanes(v, mixed), 0.5f, 1e-6f);
    std::vector<pb::raytrace::WorldTriangle> slanted = wallAt(2.0f, glm::normalize(glm::vec3(1, 1, 0)));
    EXPECT_FLOAT_EQ(surfaceOnProbePlanes(v, slanted), 0.0f);
    std::vector<pb::raytrace::WorldTriangle> outside = wallAt(9.0f);
    for (pb::raytrace::WorldTriangle t : wallAt(2.5f))
        outside.push_back(t);
    EXPECT_FLOAT_EQ(surfaceOnProbePlanes(v, outside), 0.0f); // the wall at 9 is not in it
}

TEST(LatticeAlignment, AutoKeepsTheBoundaryWallsOffItsProbePlanes) {
    // The courtyard's ground and outer walls are the scene bounds. The naive uniform fit puts
    // its outer probe planes on them; auto's lattice puts them half a cell outside and, under a
    // budget, picks among the spacings that fit one with little surface on its planes.
    const pb::scene::Scene s = pb::scene::loadScene("courtyard");
    const std::vector<pb::raytrace::WorldTriangle> triangles = pb::raytrace::staticBakeTriangles(s);
    AutoPlacementRequest uniform;
    uniform.mode = AutoMode::Uniform;
    const AutoPlacementResult u = placeAutoVolumes(s, uniform);
    AutoPlacementRequest r;
    r.sparse = true;
    r.budgetBytes = 0.5 * double(u.bytes);
    const AutoPlacementResult a = placeAutoVolumes(s, r);
    float onPlanes = 0.0f;
    for (const ProbeVolume& v : a.volumes)
        onPlanes = std::max(onPlanes, surfaceOnProbePlanes(v, triangles));
    EXPECT_FLOAT_EQ(a.onProbePlanes, onPlanes);
    EXPECT_GT(surfaceOnProbePlanes(u.volumes[0], triangles), 0.3f);
    EXPECT_LT(onPlanes, 0.1f);
    EXPECT_LE(double(a.bytes), r.budgetBytes);
}
