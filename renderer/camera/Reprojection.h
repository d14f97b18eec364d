#pragma once
// Camera-motion reprojection without motion vectors (gi.upsample=temporal): where a static
// surface seen at a pixel of this frame was on the previous frame's screen. GL-free, so the
// shader's math (shaders/gi_upsample_temporal.frag) has a tested CPU twin.
//
// The renderer is camera-relative (passes/RenderView.h): each frame's GPU positions are
// relative to that frame's eye, which may be 1e6 units from the origin. The previous frame's
// clip space is reached from this frame's camera-relative position through
//     prevClipFromRel * translate(eye - prevEye)
// composed here in double: the eye difference is small and exact in double, so the float
// matrix the GPU gets keeps full precision wherever the scene is. (Composing world-space
// matrices in float instead loses whole pixels at 1e6: tests/unit/ReprojectionTest.cpp.)
#include <glm/glm.hpp>

namespace pb::camera {

// What reprojection and cut detection need of one frame's camera (render::RenderView holds
// the same fields; passes/GiUpsamplePass converts).
struct CameraState {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0, 0, -1};
    glm::mat4 clipFromRel{1.0f}; // projection * rotation-only view
    glm::mat4 relFromClip{1.0f};
    int width = 1, height = 1;
    float fovYDegrees = 60.0f;
    float farPlane = 100.0f;
};

// prev's clip space from cur's camera-relative space (composed in double, then rounded).
glm::mat4 prevClipFromCurrentRel(const CameraState& prev, const CameraState& cur);
// cur.eye - prev.eye: a position relative to cur's eye plus this is relative to prev's eye.
glm::vec3 eyeOffset(const CameraState& prev, const CameraState& cur);
// Bit-identical eye, matrices and viewport: every pixel reprojects onto itself (the shader then
// skips the float round trip, which misses by up to a few hundredths of a pixel far away).
bool isSameCamera(const CameraState& a, const CameraState& b);

// A camera-relative position from window coordinates (x, y: pixel centre = index + 0.5, GL's
// bottom-up rows) and window depth in [0, 1], as the shaders reconstruct it (float math).
glm::vec3 relFromWindow(const CameraState& cam, glm::vec2 window, float depth);

struct PixelReprojection {
    bool inFront = false;    // in front of the previous eye (else no previous pixel exists)
    bool onScreen = false;   // inFront and inside the previous viewport
    glm::vec2 prevWindow{0}; // window coordinates in the previous frame (pixel centre = i + 0.5)
    float prevDistance = 0;  // distance of the point from the previous eye
};

// Where the surface at window position `window` with window depth `depth` in `cur` was in
// `prev`: the shader's arithmetic in float with the double-composed matrix.
PixelReprojection reprojectPixel(const CameraState& prev, const CameraState& cur, glm::vec2 window,
                                 float depth);

} // namespace pb::camera
