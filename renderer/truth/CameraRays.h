#pragma once
// The rasterizer's camera as rays: passes/RenderView builds glm::lookAt (up = +Y, or +Z when
// looking almost straight up or down) and glm::perspective(fovY, width / height); a pixel's
// ray goes through the same point of that frustum. Rows run top to bottom, as image files.
#include "scene/Scene.h"

namespace pb::truth {

class CameraRays {
public:
    // Throws pb::Error when position and target coincide (as makeRenderView does).
    CameraRays(const scene::View& view, int width, int height);
    // The unit direction through (x + jx, y + jy), jx, jy in [0, 1): 0.5 is the pixel centre.
    glm::vec3 direction(int x, int y, float jx, float jy) const;
    const glm::vec3& eye() const { return eye_; }

private:
    glm::vec3 eye_, forward_, right_, up_;
    float tanHalfY_ = 0.0f, aspect_ = 1.0f;
    int width_ = 1, height_ = 1;
};

} // namespace pb::truth
