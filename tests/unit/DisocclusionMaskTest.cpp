// The ghosting measure's ground truth (renderer/camera/DisocclusionMask.h): a camera stepping
// sideways past the edge of a wall in front of a backdrop uncovers exactly the strip of backdrop
// behind the edge (was hidden), and what enters the screen at its side is told apart.
#include "camera/DisocclusionMask.h"
#include "unit/CameraTestViews.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

constexpr int kW = 96, kH = 54;
constexpr double kWallZ = -3.0, kBackdropZ = -6.0; // the wall covers x < 0

struct Hit {
    glm::dvec3 point;
    bool backdrop;
};

Hit trace(const camera::CameraState& c, int x, int yTop) {
    const glm::dvec2 ndc((x + 0.5) / kW * 2.0 - 1.0, (kH - 1 - yTop + 0.5) / kH * 2.0 - 1.0);
    const glm::dvec4 farH = glm::dmat4(c.relFromClip) * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(farH) / farH.w);
    const double tWall = (kWallZ - c.eye.z) / dir.z;
    const glm::dvec3 wall = c.eye + tWall * dir;
    if (wall.x < 0.0) return {wall, false};
    return {c.eye + (kBackdropZ - c.eye.z) / dir.z * dir, true};
}

image::ImageF depthImage(const camera::CameraState& c) {
    image::ImageF img;
    img.width = kW;
    img.height = kH;
    img.pixels.resize(size_t(kW) * kH * 4, 0.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const ExactProjection p = projectExact(c, trace(c, x, y).point);
            img.at(x, y, 0) = float(p.distance);
            img.at(x, y, 1) = float(p.depth);
        }
    return img;
}

TEST(DisocclusionMask, SidewaysStepUncoversTheStripBehindTheEdge) {
    const camera::CameraState prev = testCamera({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, kW, kH);
    const camera::CameraState cur = testCamera({0.5, 0.0, 0.0}, {0.5, 0.0, -1.0}, kW, kH);
    const auto mask = camera::disocclusionMask(prev, depthImage(prev), cur, depthImage(cur));
    int uncovered = 0, enteredScreen = 0, wrong = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const Hit h = trace(cur, x, y);
            // Seen from the previous eye, backdrop at x < 0 was behind the wall's edge...
            const bool hidden = h.backdrop && h.point.x < 0.0;
            // ...and whatever projects outside the previous viewport was off-screen.
            const ExactProjection before = projectExact(prev, h.point);
            const bool offScreen = before.window.x < 0.0 || before.window.x > kW;
            uncovered += hidden;
            enteredScreen += offScreen && !hidden;
            const camera::PixelHistory want = offScreen ? camera::PixelHistory::EnteredScreen
                                              : hidden  ? camera::PixelHistory::WasHidden
                                                        : camera::PixelHistory::Seen;
            wrong += mask[size_t(y) * kW + x] != want;
        }
    EXPECT_GT(uncovered, kH);     // the strip is at least a column wide
    EXPECT_GT(enteredScreen, kH); // and the right edge brought new pixels
    // Pixels whose footprint straddles an edge may go either way: at most one column per edge.
    EXPECT_LE(wrong, 2 * kH) << "uncovered " << uncovered << ", entered " << enteredScreen;
}

TEST(DisocclusionMask, StillCameraUncoversNothing) {
    const camera::CameraState c = testCamera({0.3, 0.1, 0.0}, {0.0, 0.0, -1.0}, kW, kH);
    const image::ImageF d = depthImage(c);
    for (camera::PixelHistory m : camera::disocclusionMask(c, d, c, d))
        ASSERT_EQ(m, camera::PixelHistory::Seen);
}

} // namespace
} // namespace pb::test
