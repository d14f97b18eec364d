// What a RayScene hit carries besides its distance (RayHit::ng, u, v), which the bake's shading
// reads instead of the triangle arrays: hitNormal is the triangle's front-side unit normal
// (faceNormal) for hits on either side, on plain and on mirrored instances; (u, v) are the
// barycentrics of the hit point against triangleCorners; and the lit-surface patch found from
// them is the one found from the hit point.
#include "ProbeTestScenes.h"
#include "probes/bake/LitSurfaces.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pb;
using namespace pb::probes;
using namespace pb::test;

namespace {

// A closed box of 1 m around the origin (walls facing inwards), and a second, mirrored copy
// (scale -1 in x: its triangles wind the other way in world space) shifted 3 m along +x.
scene::Scene boxAndMirroredBox() {
    scene::Scene s = emptyScene(glm::vec3(0.0f));
    const int grey = addMaterial(s, glm::vec3(0.5f), glm::vec3(0.0f), true);
    addInstance(s, boxPrimitive(glm::vec3(-0.5f), glm::vec3(0.5f), true, grey));
    glm::mat4 mirror(1.0f);
    mirror[0][0] = -1.0f;
    mirror[3] = glm::vec4(3.0f, 0.0f, 0.0f, 1.0f);
    addInstance(s, boxPrimitive(glm::vec3(-0.5f), glm::vec3(0.5f), true, grey), mirror);
    return s;
}

// Rays from a point inside each box (front faces) and from one between them (back faces:
// the walls face inwards).
std::vector<std::pair<glm::vec3, glm::vec3>> rayHitTestRays() {
    std::vector<std::pair<glm::vec3, glm::vec3>> rays;
    const std::vector<glm::vec3> dirs = sphericalFibonacci(200);
    for (const glm::vec3& o : {glm::vec3(0.1f, -0.05f, 0.02f), glm::vec3(3.05f, 0.1f, -0.1f),
                               glm::vec3(1.5f, 0.1f, 0.05f)})
        for (const glm::vec3& d : dirs)
            rays.emplace_back(o, d);
    return rays;
}

} // namespace

TEST(RaySceneHit, HitNormalIsTheFrontFaceNormalOnPlainAndMirroredInstances) {
    const pb::raytrace::RayScene rs(boxAndMirroredBox());
    int front = 0, back = 0, mirrored = 0;
    for (const auto& [o, d] : rayHitTestRays()) {
        const pb::raytrace::RayHit h = rs.intersect(o, d);
        if (!h.hit()) continue;
        const glm::vec3 stored = rs.faceNormal(h.geomID, h.primID), fromHit = rs.hitNormal(h);
        EXPECT_NEAR(glm::length(fromHit), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(stored, fromHit), 1.0f, 1e-6f) << "geometry " << h.geomID;
        (glm::dot(fromHit, d) < 0.0f ? front : back) += 1;
        mirrored += o.x > 2.0f && h.geomID == 1;
    }
    // Both sides and the mirrored copy were hit, or the test checked less than it says.
    EXPECT_GT(front, 100);
    EXPECT_GT(back, 10);
    EXPECT_GT(mirrored, 100);
}

TEST(RaySceneHit, BarycentricsLocateTheHitPointOnItsTriangle) {
    const pb::raytrace::RayScene rs(boxAndMirroredBox());
    int hits = 0;
    for (const auto& [o, d] : rayHitTestRays()) {
        const pb::raytrace::RayHit h = rs.intersect(o, d);
        if (!h.hit()) continue;
        ++hits;
        glm::vec3 a, b, c;
        rs.triangleCorners(h.geomID, h.primID, a, b, c);
        const glm::vec3 x = o + d * h.t, fromUv = a + h.u * (b - a) + h.v * (c - a);
        EXPECT_NEAR(glm::length(x - fromUv), 0.0f, 1e-5f);
        EXPECT_GE(h.u, 0.0f);
        EXPECT_GE(h.v, 0.0f);
        EXPECT_LE(h.u + h.v, 1.0f + 1e-6f);
    }
    EXPECT_GT(hits, 400);
}

TEST(RaySceneHit, LitPatchFromBarycentricsIsThePatchOfTheHitPoint) {
    const scene::Scene s = boxAndMirroredBox();
    const pb::raytrace::RayScene rs(s);
    std::uint64_t shadow = 0;
    // The boxes are closed: a point light inside each lights its walls.
    std::vector<scene::Light> lights(2);
    for (int i = 0; i < 2; ++i) {
        lights[size_t(i)].type = scene::LightType::Point;
        lights[size_t(i)].position = glm::vec3(3.0f * float(i), 0.2f, 0.0f);
        lights[size_t(i)].intensity = 1.0f;
        lights[size_t(i)].color = glm::vec3(1.0f);
    }
    Scenario sc;
    sc.sun.enabled = false;
    const LitSurfaces lit(rs, sc, lights, 2, shadow);
    ASSERT_FALSE(lit.empty());
    int lookedUp = 0, differ = 0;
    for (const auto& [o, d] : rayHitTestRays()) {
        const pb::raytrace::RayHit h = rs.intersect(o, d);
        if (!h.hit()) continue;
        const bool back = glm::dot(rs.hitNormal(h), d) > 0.0f;
        const std::int64_t fromPoint = lit.slotOf(h.geomID, h.primID, back, o + d * h.t);
        const std::int64_t fromUv = lit.slotOfBarycentric(h.geomID, h.primID, back, h.u, h.v);
        differ += fromUv != fromPoint;
        lookedUp += fromUv >= 0;
    }
    EXPECT_GT(lookedUp, 400); // lit patches were found, not only "nothing sampled here"
    // The two barycentrics differ in their last bits, so a hit within about 1e-6 of a patch
    // edge (16 patches per wall edge here: ~1e-4 of the hits) may fall on either side.
    EXPECT_LE(differ, 2);
}

TEST(RaySceneHit, AProbesRaysInOneCallHitWhatEachRayHitsAlone) {
    const pb::raytrace::RayScene rs(boxAndMirroredBox());
    const std::vector<glm::vec3> dirs = sphericalFibonacci(200);
    int hits = 0, misses = 0;
    // Inside a box (every ray hits) and between the boxes (some rays leave the scene).
    for (const glm::vec3& o : {glm::vec3(0.1f, -0.05f, 0.02f), glm::vec3(1.5f, 0.1f, 0.05f)}) {
        std::vector<pb::raytrace::RayHit> fan(dirs.size());
        rs.intersect(o, dirs.data(), dirs.size(), fan.data());
        for (std::size_t i = 0; i < dirs.size(); ++i) {
            const pb::raytrace::RayHit one = rs.intersect(o, dirs[i]);
            const pb::raytrace::RayHit& h = fan[i];
            ASSERT_EQ(h.hit(), one.hit()) << "ray " << i;
            (one.hit() ? hits : misses) += 1;
            if (!one.hit()) continue;
            EXPECT_EQ(h.t, one.t);
            EXPECT_EQ(h.geomID, one.geomID);
            EXPECT_EQ(h.primID, one.primID);
            EXPECT_EQ(h.ng, one.ng);
            EXPECT_EQ(h.u, one.u);
            EXPECT_EQ(h.v, one.v);
        }
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 10);
}
