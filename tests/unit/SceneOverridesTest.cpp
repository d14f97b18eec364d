// --sun, --sky, --camera parsing: good specs apply, bad ones give one-line errors naming the
// option and the value.
#include "core/Error.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace pb::scene;

namespace {

// Runs `f`, expects a pb::Error whose one-line message contains every piece of `parts`.
template <typename F> void expectError(F&& f, std::initializer_list<std::string> parts) {
    try {
        f();
        ADD_FAILURE() << "no error for " << *parts.begin();
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        for (const std::string& p : parts)
            EXPECT_NE(msg.find(p), std::string::npos) << msg;
    }
}

} // namespace

TEST(SceneOverrides, SunDirectionIsNormalisedAndIntensityOptional) {
    Scene s;
    const float before = s.sun.intensity;
    applySunOverride(s, "0,2,0");
    EXPECT_TRUE(s.sun.enabled);
    EXPECT_EQ(s.sun.toSun, glm::vec3(0, 1, 0));
    EXPECT_EQ(s.sun.intensity, before);
    applySunOverride(s, " 3, 0 ,4 ,7.5");
    EXPECT_NEAR(s.sun.toSun.x, 0.6f, 1e-6f);
    EXPECT_NEAR(s.sun.toSun.z, 0.8f, 1e-6f);
    EXPECT_EQ(s.sun.intensity, 7.5f);
    applySunOverride(s, "off");
    EXPECT_FALSE(s.sun.enabled);
    applySunOverride(s, "1,1,1,0"); // a zero intensity is allowed (sun present but black)
    EXPECT_TRUE(s.sun.enabled);
    EXPECT_EQ(s.sun.intensity, 0.0f);
}

TEST(SceneOverrides, SunRejectsBadSpecs) {
    Scene s;
    for (const char* bad : {"", "on", "1,2", "1,2,3,4,5", "1,,2", "1,2,x", "nan,1,1", "1,2,3,",
                            "inf,0,0", "1e50,0,0"})
        expectError([&] { applySunOverride(s, bad); }, {"--sun", std::string("'") + bad + "'"});
    expectError([&] { applySunOverride(s, "0,0,0"); }, {"--sun", "'0,0,0'", "zero"});
    expectError([&] { applySunOverride(s, "0,1,0,-2"); }, {"--sun", "negative"});
}

TEST(SceneOverrides, Sky) {
    Scene s;
    applySkyOverride(s, "1,1,1");
    EXPECT_EQ(s.sky.radiance, glm::vec3(1.0f));
    applySkyOverride(s, "0,0.5,2");
    EXPECT_EQ(s.sky.radiance, glm::vec3(0, 0.5f, 2));
    for (const char* bad : {"", "1,1", "1,1,1,1", "a,b,c", "1;1;1"})
        expectError([&] { applySkyOverride(s, bad); }, {"--sky", std::string("'") + bad + "'"});
    expectError([&] { applySkyOverride(s, "1,-0.1,1"); }, {"--sky", "'1,-0.1,1'", "negative"});
}

TEST(SceneOverrides, Camera) {
    const View v = parseCameraSpec("1,2,3,4,5,6");
    EXPECT_EQ(v.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(v.target, glm::vec3(4, 5, 6));
    EXPECT_EQ(v.fovYDegrees, 60.0f);
    EXPECT_FALSE(v.name.empty());
    EXPECT_EQ(parseCameraSpec("0,0,0,0,0,-1,90").fovYDegrees, 90.0f);
    for (const char* bad : {"", "1,2,3", "1,2,3,4,5,6,7,8", "1,2,3,4,5,x"})
        expectError([&] { parseCameraSpec(bad); }, {"--camera", std::string("'") + bad + "'"});
    for (const char* fov : {"0", "180", "-5", "200"})
        expectError([&] { parseCameraSpec(std::string("0,0,0,1,0,0,") + fov); },
                    {"--camera", "field of view"});
    expectError([&] { parseCameraSpec("1,1,1,1,1,1"); }, {"--camera", "differ"});
}
