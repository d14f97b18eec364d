// Camera paths (renderer/camera/CameraPath.h): TOML files with cuts, interpolation, the
// built-in paths, and one-line errors naming file and line.
#include "camera/CameraPath.h"
#include "core/Error.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

const char* kThreeKeys = R"(name = "test"
fps = 10
[[key]]
time = 0.0
position = [0, 1, 0]
target = [0, 1, -1]
fov = 50
[[key]]
time = 1.0
position = [2, 1, 0]
target = [2, 1, -1]
[[key]]
time = 2.0
position = [10, 1, 0]
target = [10, 1, -1]
cut = true
)";

TEST(CameraPath, FileKeysInterpolateAndCutsJump) {
    const camera::CameraPath p = camera::parseCameraPathToml(kThreeKeys, "t.toml");
    EXPECT_EQ(p.name, "test");
    EXPECT_EQ(p.fps, 10.0);
    ASSERT_EQ(p.keys.size(), 3u);
    EXPECT_EQ(p.keys[1].fovYDegrees, 50.0f) << "fov carries over from the previous key";
    EXPECT_EQ(p.naturalFrameCount(), 21);
    const auto frames = camera::playPath(p, 25);
    ASSERT_EQ(frames.size(), 25u);
    EXPECT_TRUE(frames[0].cut);
    EXPECT_NEAR(frames[5].view.position.x, 1.0f, 1e-5f); // halfway between key 0 and 1
    // Before the cut key the camera holds key 1 instead of sliding towards the cut.
    EXPECT_NEAR(frames[15].view.position.x, 2.0f, 1e-5f);
    EXPECT_FALSE(frames[19].cut);
    EXPECT_TRUE(frames[20].cut);
    EXPECT_NEAR(frames[20].view.position.x, 10.0f, 1e-5f);
    EXPECT_FALSE(frames[21].cut);
    EXPECT_NEAR(frames[24].view.position.x, 10.0f, 1e-5f) << "holds after the last key";
    for (int i = 1; i < 20; ++i)
        EXPECT_FALSE(frames[size_t(i)].cut) << i;
}

TEST(CameraPath, FileErrorsNameFileAndLine) {
    struct Case {
        const char* text;
        const char* mustContain;
    };
    const Case cases[] = {
        {"[[key]]\ntime = 0\nposition = [0,0,0]\n", "t.toml:1: [[key]] #1: missing key 'target'"},
        {"[[key]]\ntime = 0\nposition = [0,0,0]\ntarget = [1,0,0]\n[[key]]\ntime = 0\n"
         "position = [0,0,0]\ntarget = [1,0,0]\n",
         "t.toml:6: [[key]] #2: 'time' must increase"},
        {"[[key]]\ntime = 1\nposition = [0,0,0]\ntarget = [1,0,0]\n",
         "first key's 'time' must be 0"},
        {"[[key]]\ntime = 0\nposition = [0,0]\ntarget = [1,0,0]\n", "array of 3 numbers"},
        {"[[key]]\ntime = 0\nposition = [0,0,0]\ntarget = [0,0,0]\n", "coincide"},
        {"[[key]]\ntime = 0\nposition = [0,0,0]\ntarget = [1,0,0]\nfov = 200\n", "'fov' must be"},
        {"[[key]]\ntime = 0\nposition = [0,0,0]\ntarget = [1,0,0]\nspeed = 2\n",
         "t.toml:5: unknown key 'speed'"},
        {"fps = 30\n", "no [[key]] tables"},
        {"fps = \n", "TOML syntax error"},
        {"[[key]]\ntime = 0\nposition = [0,0,0]\ntarget = [1,0,0]\ncut = 1\n", "true or false"},
    };
    for (const Case& c : cases) {
        try {
            camera::parseCameraPathToml(c.text, "t.toml");
            ADD_FAILURE() << "accepted:\n" << c.text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.mustContain), std::string::npos)
                << e.what() << "\nexpected: " << c.mustContain;
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
        }
    }
}

double yawDegrees(const scene::View& v) {
    const glm::vec3 d = v.target - v.position;
    return glm::degrees(std::atan2(double(-d.x), double(-d.z)));
}

TEST(CameraPath, BuiltinTurnsHaveTheirAngularSpeed) {
    const scene::Scene s = scene::makeBuiltinScene("cornell");
    const scene::View start = s.views.front();
    const auto still = camera::playPath(camera::makeBuiltinPath("static", s, start), 0 + 30);
    for (const auto& f : still)
        EXPECT_EQ(f.view.position, start.position);
    const auto slow = camera::playPath(camera::makeBuiltinPath("slow_pan", s, start), 31);
    EXPECT_NEAR(yawDegrees(slow[30].view) - yawDegrees(slow[0].view), 10.0, 0.01);
    const camera::CameraPath fastPath = camera::makeBuiltinPath("fast_turn", s, start);
    EXPECT_EQ(fastPath.naturalFrameCount(), 61);
    const auto fast = camera::playPath(fastPath, 61);
    double step = yawDegrees(fast[6].view) - yawDegrees(fast[5].view);
    EXPECT_NEAR(step, 6.0, 0.01);
    EXPECT_EQ(fast[45].view.target, fast[60].view.target) << "still for the last second";
}

TEST(CameraPath, DoorwayWalkGoesThroughTheRoomsDoorway) {
    const scene::Scene rooms = scene::makeBuiltinScene("rooms");
    const camera::CameraPath p = camera::makeBuiltinPath("doorway_walk", rooms, rooms.views[0]);
    const auto frames = camera::playPath(p, p.naturalFrameCount());
    bool crossed = false;
    for (size_t i = 1; i < frames.size(); ++i) {
        const glm::vec3 a = frames[i - 1].view.position, b = frames[i].view.position;
        if (a.x > 0.0f && b.x <= 0.0f) {
            crossed = true;
            // The partition's doorway: z in [-0.45, 0.45], y below the lintel at 2.1.
            EXPECT_LT(std::abs(b.z), 0.45f);
            EXPECT_LT(b.y, 2.1f);
        }
        EXPECT_LT(glm::length(b - a), 0.06f) << "1.5 m/s at 30 fps";
    }
    EXPECT_TRUE(crossed);
    EXPECT_GT(frames.front().view.position.x, 2.0f);
    EXPECT_LT(frames.back().view.position.x, -2.0f);
    const scene::Scene cornell = scene::makeBuiltinScene("cornell");
    EXPECT_THROW(camera::makeBuiltinPath("doorway_walk", cornell, cornell.views[0]), Error);
    EXPECT_THROW(camera::makeBuiltinPath("spiral", cornell, cornell.views[0]), Error);
}

} // namespace
} // namespace pb::test
