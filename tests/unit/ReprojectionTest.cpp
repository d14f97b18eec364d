// Camera-motion reprojection (renderer/camera/Reprojection.h), the CPU twin of
// gi_upsample_temporal.frag: a known world point seen in this frame lands on the previous
// frame's pixel that saw it, near the origin and 1e6 units away from it.
#include "unit/CameraTestViews.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

// Moves and turns a little between frames, as a walking camera does.
struct TwoFrames {
    camera::CameraState prev, cur;
};

// A 720p frame: what a pixel error means there.
constexpr int kReprojectionW = 1280, kReprojectionH = 720;

TwoFrames walkingCameras(glm::dvec3 origin) {
    return {testCamera(origin + glm::dvec3(0.0, 1.6, 4.0), origin + glm::dvec3(0.0, 1.0, 0.0),
                       kReprojectionW, kReprojectionH),
            testCamera(origin + glm::dvec3(0.25, 1.65, 3.7), origin + glm::dvec3(0.4, 0.9, 0.0),
                       kReprojectionW, kReprojectionH)};
}

const glm::dvec3 kPoints[] = {{0.2, 0.5, -0.3}, {-1.0, 1.8, 0.5}, {0.9, 0.1, -2.0}};

void expectLandsOnPreviousPixel(glm::dvec3 origin) {
    const TwoFrames f = walkingCameras(origin);
    for (glm::dvec3 p : kPoints) {
        const glm::dvec3 world = origin + p;
        const ExactProjection now = projectExact(f.cur, world);
        const ExactProjection before = projectExact(f.prev, world);
        const camera::PixelReprojection r =
            camera::reprojectPixel(f.prev, f.cur, glm::vec2(now.window), float(now.depth));
        ASSERT_TRUE(r.onScreen) << "point " << p.x << "," << p.y << "," << p.z;
        EXPECT_NEAR(r.prevWindow.x, before.window.x, 0.05);
        EXPECT_NEAR(r.prevWindow.y, before.window.y, 0.05);
        EXPECT_NEAR(r.prevDistance, before.distance, 1e-3 * before.distance);
    }
}

TEST(Reprojection, KnownPointLandsOnThePreviousPixelNearTheOrigin) {
    expectLandsOnPreviousPixel(glm::dvec3(0.0));
}

TEST(Reprojection, KnownPointLandsOnThePreviousPixelFarFromTheOrigin) {
    expectLandsOnPreviousPixel(glm::dvec3(1.0e6, -2.0e5, -3.0e6));
}

// The scenario above is sensitive: composing world-space matrices in float (the mistake the
// camera-relative design avoids) misses by many pixels out there.
TEST(Reprojection, FloatWorldMatricesWouldMissFarFromTheOrigin) {
    const glm::dvec3 origin(1.0e6, -2.0e5, -3.0e6);
    const TwoFrames f = walkingCameras(origin);
    const glm::dvec3 world = origin + kPoints[0];
    const glm::mat4 prevWorld =
        f.prev.clipFromRel * glm::translate(glm::mat4(1.0f), -glm::vec3(f.prev.eye));
    const glm::vec4 clip = prevWorld * glm::vec4(glm::vec3(world), 1.0f);
    const glm::vec2 naive =
        (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kReprojectionW, kReprojectionH);
    const ExactProjection before = projectExact(f.prev, world);
    EXPECT_GT(glm::length(glm::dvec2(naive) - before.window), 1.0);
}

TEST(Reprojection, StillCameraMapsEveryPixelOntoItself) {
    const camera::CameraState c = testCamera({5e5, 2.0, 5e5}, {5e5 - 3.0, 1.0, 5e5 + 1.0});
    for (glm::vec2 w : {glm::vec2(0.5f, 0.5f), glm::vec2(80.5f, 45.5f), glm::vec2(159.5f, 89.5f)})
        for (float depth : {0.5f, 0.99f, 0.9999f}) {
            const camera::PixelReprojection r = camera::reprojectPixel(c, c, w, depth);
            EXPECT_NEAR(r.prevWindow.x, w.x, 1e-3);
            EXPECT_NEAR(r.prevWindow.y, w.y, 1e-3);
        }
}

TEST(Reprojection, SameCameraMeansBitIdenticalEyeMatricesAndViewport) {
    const camera::CameraState a = testCamera({5e5, 2.0, 5e5}, {5e5 - 3.0, 1.0, 5e5 + 1.0});
    EXPECT_TRUE(camera::isSameCamera(a, a));
    camera::CameraState b = a;
    b.eye.x += 1e-9; // below float, not below double: the shader would still have to reproject
    EXPECT_FALSE(camera::isSameCamera(a, b));
    b = testCamera({5e5, 2.0, 5e5}, {5e5 - 3.0, 1.0, 5e5 + 1.001});
    EXPECT_FALSE(camera::isSameCamera(a, b));
    b = testCamera({5e5, 2.0, 5e5}, {5e5 - 3.0, 1.0, 5e5 + 1.0}, 161, 90);
    EXPECT_FALSE(camera::isSameCamera(a, b));
}

TEST(Reprojection, PointsBehindOrBesideThePreviousCameraHaveNoPreviousPixel) {
    const camera::CameraState prev = testCamera({0, 1, 0}, {0, 1, -1});
    // Turned around: what is in front now was behind before.
    const camera::CameraState back = testCamera({0, 1, 0}, {0, 1, 1});
    const ExactProjection p = projectExact(back, {0.1, 1.0, 3.0});
    camera::PixelReprojection r =
        camera::reprojectPixel(prev, back, glm::vec2(p.window), float(p.depth));
    EXPECT_FALSE(r.inFront);
    EXPECT_FALSE(r.onScreen);
    // Turned 90 degrees: in front of both eyes but outside the previous viewport.
    const camera::CameraState side = testCamera({0, 1, 0}, {1, 1, 0});
    const ExactProjection q = projectExact(side, {3.0, 1.0, 0.1});
    r = camera::reprojectPixel(prev, side, glm::vec2(q.window), float(q.depth));
    EXPECT_FALSE(r.onScreen);
}

TEST(Reprojection, EyeOffsetKeepsCentimetresAtAMillionUnits) {
    const camera::CameraState a = testCamera({1e6, 0, 1e6}, {1e6, 0, 1e6 - 1});
    const camera::CameraState b = testCamera({1e6 + 0.013, 0.002, 1e6}, {1e6, 0, 1e6 - 1});
    const glm::vec3 o = camera::eyeOffset(a, b);
    EXPECT_NEAR(o.x, 0.013f, 1e-6f);
    EXPECT_NEAR(o.y, 0.002f, 1e-6f);
    EXPECT_EQ(o.z, 0.0f);
}

} // namespace
} // namespace pb::test
