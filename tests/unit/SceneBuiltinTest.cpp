// The built-in procedural scenes: closed where they must be, the 5 cm wall, the sun reaching
// only the sunlit room, outward-facing geometry, and their views.
#include "core/Error.h"
#include "scene/RayGrid.h"
#include "scene/SceneLoader.h"
#include "unit/SceneRaycast.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace pb::scene;
using pb::test::SceneRaycaster;

namespace {

const Instance* findInstance(const Scene& s, const std::string& name) {
    for (const Instance& i : s.instances)
        if (i.nodeName == name) return &i;
    return nullptr;
}

Bounds instanceWorldBounds(const Scene& s, const Instance& inst) {
    Bounds b;
    const Primitive& p = s.primitives[size_t(inst.primitive)];
    for (std::uint32_t v = 0; v < p.positions.size(); ++v)
        b.extend(worldPosition(s, inst, v));
    return b;
}

} // namespace

TEST(SceneBuiltin, NamesAndUnknownName) {
    for (const char* n : {"cornell", "rooms", "courtyard", "empty"})
        EXPECT_TRUE(isBuiltinScene(n));
    EXPECT_FALSE(isBuiltinScene("sponza"));
    try {
        makeBuiltinScene("sponza");
        FAIL();
    } catch (const pb::Error& e) {
        EXPECT_NE(std::string(e.what()).find("cornell, rooms, courtyard, empty"),
                  std::string::npos);
    }
}

TEST(SceneBuiltin, EverySceneIsWellFormed) {
    for (const std::string& name : builtinSceneNames()) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(name);
        EXPECT_EQ(s.name, name);
        EXPECT_FALSE(s.materials.empty());
        ASSERT_FALSE(s.views.empty());
        EXPECT_EQ(s.views.front().name, "default");
        EXPECT_GT(s.exposure, 0.0f);
        if (name != "empty") {
            EXPECT_GE(s.views.size(), 3u) << "default + at least 2 named views";
        }
        for (const View& v : s.views)
            EXPECT_NE(v.position, v.target) << v.name;
        // Only rooms_dynamic has dynamic objects (issue 18): its three boxes in the air.
        int dynamic = 0;
        for (const Instance& inst : s.instances)
            dynamic += inst.dynamic ? 1 : 0;
        EXPECT_EQ(dynamic, name == "rooms_dynamic" ? 3 : 0);
        for (const Primitive& p : s.primitives) {
            ASSERT_EQ(p.normals.size(), p.positions.size());
            // Outward normals, counter-clockwise winding: the face normal from the winding
            // agrees with the stored normal.
            for (size_t t = 0; t < p.indices.size(); t += 3) {
                const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]],
                                c = p.positions[p.indices[t + 2]];
                const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
                EXPECT_GT(glm::dot(face, p.normals[p.indices[t]]), 0.99f);
            }
        }
    }
    EXPECT_EQ(loadScene("empty").triangleCount(), 0u);
}

TEST(SceneBuiltin, CornellIsClosedAndLitOnlyByItsPanel) {
    const Scene s = makeBuiltinScene("cornell");
    EXPECT_FALSE(s.sun.enabled);
    EXPECT_EQ(s.sky.radiance, glm::vec3(0.0f));
    EXPECT_TRUE(s.lights.empty());
    int emissive = 0;
    for (const Material& m : s.materials)
        emissive += glm::length(m.emissive) > 0.0f;
    EXPECT_EQ(emissive, 1);
    ASSERT_NE(s.findView("front"), nullptr);

    const SceneRaycaster rc(s);
    const auto dirs = pb::test::sphereDirections(2000);
    // The centre, and points near the corners and edges where a crack would show.
    for (const glm::vec3 o : {glm::vec3(0, 1, 0), glm::vec3(0.95f, 1.95f, 0.95f),
                              glm::vec3(-0.97f, 0.03f, 0.97f), glm::vec3(0.98f, 1.0f, -0.98f)}) {
        int escaped = 0;
        for (const glm::vec3& d : dirs)
            escaped += !rc.hits(o, d);
        EXPECT_EQ(escaped, 0) << "rays escape from (" << o.x << "," << o.y << "," << o.z << ")";
    }
}

TEST(SceneBuiltin, RoomsHaveA5cmPartitionAndTheSunOnlyInTheSunlitRoom) {
    const Scene s = makeBuiltinScene("rooms");
    for (const char* v : {"sunlit_room", "dark_room", "doorway"})
        EXPECT_NE(s.findView(v), nullptr) << v;
    for (const char* part : {"partition_south", "partition_north", "partition_lintel"}) {
        const Instance* inst = findInstance(s, part);
        ASSERT_NE(inst, nullptr) << part;
        const Bounds b = instanceWorldBounds(s, *inst);
        EXPECT_NEAR(b.size().x, 0.05f, 1e-5f) << part;
    }
    ASSERT_TRUE(s.sun.enabled);
    const SceneRaycaster rc(s);
    // No point in the dark room (x > 0) sees the sun; some of the sunlit floor does.
    int sunlitDark = 0, sunlitLight = 0;
    for (float x = 0.1f; x < 4.0f; x += 0.25f)
        for (float z = -2.4f; z < 2.5f; z += 0.25f)
            for (float y : {0.01f, 1.0f, 2.0f})
                sunlitDark += !rc.hits({x, y, z}, s.sun.toSun);
    for (float x = -3.9f; x < 0.0f; x += 0.25f)
        for (float z = -2.4f; z < 2.5f; z += 0.25f)
            sunlitLight += !rc.hits({x, 0.01f, z}, s.sun.toSun);
    EXPECT_EQ(sunlitDark, 0);
    EXPECT_GT(sunlitLight, 5);
    // The dark room is closed except for the doorway: a ray that escapes to the sky must
    // cross the partition plane inside the doorway opening.
    const auto dirs = pb::test::sphereDirections(1000);
    const glm::vec3 o(2.8f, 1.2f, -1.0f);
    for (const glm::vec3& d : dirs) {
        if (rc.hits(o, d)) continue;
        ASSERT_LT(d.x, 0.0f);
        const float t = -o.x / d.x;
        const glm::vec3 p = o + d * t;
        EXPECT_LT(std::abs(p.z), 0.46f);
        EXPECT_LT(p.y, 2.11f);
    }
}

TEST(SceneBuiltin, CourtyardHasSunSkyAndAHollowHall) {
    const Scene s = makeBuiltinScene("courtyard");
    EXPECT_TRUE(s.sun.enabled);
    EXPECT_GT(glm::length(s.sky.radiance), 0.0f);
    for (const char* v : {"overview", "courtyard", "interior"})
        EXPECT_NE(s.findView(v), nullptr) << v;
    const SceneRaycaster rc(s);
    const View& in = *s.findView("interior");
    EXPECT_TRUE(rc.hits(in.position, {0, 1, 0})) << "the hall has a roof";
    EXPECT_FALSE(rc.hits(s.findView("courtyard")->position, {0, 1, 0})) << "the courtyard is open";
    // The interior view looks at the inside of the door wall, the courtyard view into the door.
    EXPECT_GT(rc.cast(s.findView("courtyard")->position,
                      s.findView("courtyard")->target - s.findView("courtyard")->position),
              11.0);
}

TEST(SceneBuiltin, DynamicNodesByNameOnBuiltinScenes) {
    SceneOptions opts;
    opts.dynamicNodes = {"tall_box"};
    const Scene s = loadScene("cornell", opts);
    EXPECT_TRUE(findInstance(s, "tall_box")->dynamic);
    EXPECT_FALSE(findInstance(s, "short_box")->dynamic);
    opts.dynamicNodes = {"no_such_box"};
    try {
        loadScene("cornell", opts);
        FAIL();
    } catch (const pb::Error& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_box"), std::string::npos);
    }
}

TEST(SceneBuiltin, UnknownSceneArgument) {
    try {
        loadScene("nonsense");
        FAIL();
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("nonsense: ", 0), 0u) << msg;
        EXPECT_NE(msg.find("cornell"), std::string::npos) << msg;
    }
}

TEST(SceneBuiltin, NoViewStartsInsideAnObject) {
    for (const std::string& name : builtinSceneNames()) {
        const Scene s = makeBuiltinScene(name);
        const RayGrid grid(s);
        for (const View& v : s.views) {
            SCOPED_TRACE(name + " view " + v.name);
            if (grid.empty()) continue;
            // Every box is closed and single-sided: from inside one, every ray meets a back face.
            int backFacing = 0;
            for (const glm::vec3& d : pb::test::sphereDirections(64))
                backFacing += grid.cast(v.position, d, 1e3f).backFacing;
            EXPECT_EQ(backFacing, 0);
            const pb::scene::RayHit centre =
                grid.cast(v.position, glm::normalize(v.target - v.position), 1e3f);
            EXPECT_GT(centre.distance, 0.5f);
        }
    }
}

TEST(SceneBuiltin, RayGridAgreesWithBruteForce) {
    const Scene s = makeBuiltinScene("courtyard");
    const RayGrid grid(s);
    const SceneRaycaster brute(s);
    const auto dirs = pb::test::sphereDirections(300);
    for (const glm::vec3 o : {glm::vec3(0, 1.7f, 6), glm::vec3(-9, 2, 0), glm::vec3(15, 30, -18)})
        for (const glm::vec3& d : dirs) {
            const double expected = brute.cast(o, d);
            const float got = grid.cast(o, d, 1e4f).distance;
            if (std::isinf(expected))
                EXPECT_TRUE(std::isinf(got));
            else
                EXPECT_NEAR(got, expected, 1e-3 * std::max(1.0, expected));
        }
}
