// The GL-free decisions of gi.upsample=temporal (renderer/camera/TemporalSampling.h): the
// jitter sequence covers every pixel of a low-resolution texel's footprint once per period,
// and the cut rule separates a moving camera from a jumping one.
#include "camera/TemporalSampling.h"
#include "unit/CameraTestViews.h"

#include <gtest/gtest.h>
#include <set>
#include <stdexcept>
#include <utility>

namespace pb::test {
namespace {

TEST(GiJitter, EveryFootprintPixelOncePerPeriodStartingAtTheCentre) {
    for (int div : {2, 4, 8}) {
        const int period = camera::jitterPeriod(div);
        ASSERT_EQ(period, div * div);
        EXPECT_EQ(camera::giJitter(div, 0), glm::ivec2((div - 1) / 2)) << "divisor " << div;
        std::set<std::pair<int, int>> seen;
        for (int k = 0; k < period; ++k) {
            const glm::ivec2 j = camera::giJitter(div, std::uint64_t(k));
            EXPECT_GE(j.x, 0);
            EXPECT_GE(j.y, 0);
            EXPECT_LT(j.x, div);
            EXPECT_LT(j.y, div);
            seen.insert({j.x, j.y});
            EXPECT_EQ(j, camera::giJitter(div, std::uint64_t(k + period))) << "repeats";
        }
        EXPECT_EQ(int(seen.size()), period) << "divisor " << div << " must visit every pixel";
    }
    EXPECT_EQ(camera::giJitter(1, 7), glm::ivec2(0));
}

TEST(GiJitter, ConsecutiveSamplesAreFarApart) {
    // Ordered dither: the second sample of a half-resolution footprint is the opposite corner.
    EXPECT_EQ(camera::giJitter(2, 1), glm::ivec2(1, 1));
    for (int k = 0; k < 16; ++k) {
        const glm::ivec2 a = camera::giJitter(4, std::uint64_t(k)),
                         b = camera::giJitter(4, std::uint64_t(k + 1));
        const glm::ivec2 d = glm::abs(a - b);
        EXPECT_GE(std::max(std::min(d.x, 4 - d.x), std::min(d.y, 4 - d.y)), 1);
    }
}

TEST(GiJitter, RejectsDivisorsThatAreNotPowersOfTwo) {
    EXPECT_THROW(camera::giJitter(3, 0), std::invalid_argument);
    EXPECT_THROW(camera::giJitter(0, 0), std::invalid_argument);
    EXPECT_THROW(camera::giJitter(32, 0), std::invalid_argument);
}

TEST(CameraCut, MovingIsNotACutJumpingIs) {
    const glm::dvec3 eye(2.0, 1.6, 3.0), target(0.0, 1.0, 0.0);
    const camera::CameraState a = testCamera(eye, target); // far plane 100
    EXPECT_FALSE(camera::isCameraCut(a, a));
    // A walking step (5 cm) and a fast turn (6 degrees) are motion.
    EXPECT_FALSE(camera::isCameraCut(a, testCamera(eye + glm::dvec3(0.05, 0, 0), target)));
    const glm::dvec3 look = target - eye;
    const double t = glm::radians(6.0);
    const glm::dvec3 turned(std::cos(t) * look.x + std::sin(t) * look.z, look.y,
                            -std::sin(t) * look.x + std::cos(t) * look.z);
    EXPECT_FALSE(camera::isCameraCut(a, testCamera(eye, eye + turned)));
    // Beyond the rule: 11% of the far plane in one frame, 90 degrees, a zoom, a resize.
    EXPECT_TRUE(camera::isCameraCut(a, testCamera(eye + glm::dvec3(0, 0, 11.0), target)));
    EXPECT_TRUE(camera::isCameraCut(a, testCamera(eye, eye + glm::dvec3(look.z, 0, -look.x))));
    EXPECT_TRUE(camera::isCameraCut(a, testCamera(eye, target, 160, 90, 50.0)));
    EXPECT_TRUE(camera::isCameraCut(a, testCamera(eye, target, 320, 180)));
    // The limits are the rule's, not constants.
    camera::CameraCutRule strict;
    strict.maxTurnDegrees = 3.0;
    EXPECT_TRUE(camera::isCameraCut(a, testCamera(eye, eye + turned), strict));
}

} // namespace
} // namespace pb::test
