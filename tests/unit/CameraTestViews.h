#pragma once
// Camera states built exactly as passes/RenderView.cpp builds its matrices (rotation-only view
// at the origin, perspective, composed in double), for the GL-free reprojection tests.
#include "camera/Reprojection.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pb::test {

inline camera::CameraState testCamera(glm::dvec3 eye, glm::dvec3 target, int w = 160, int h = 90,
                                      double fov = 60.0, double nearPlane = 0.01,
                                      double farPlane = 100.0) {
    camera::CameraState c;
    c.eye = eye;
    c.forward = glm::normalize(target - eye);
    c.width = w;
    c.height = h;
    c.fovYDegrees = float(fov);
    c.farPlane = float(farPlane);
    const glm::dvec3 up = std::abs(c.forward.y) > 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dmat4 clip =
        glm::perspective(glm::radians(fov), double(w) / double(h), nearPlane, farPlane) *
        glm::lookAt(glm::dvec3(0.0), c.forward, up);
    c.clipFromRel = glm::mat4(clip);
    c.relFromClip = glm::mat4(glm::inverse(clip));
    return c;
}

// The exact (double) window position and window depth of a world point.
struct ExactProjection {
    glm::dvec2 window;
    double depth;
    double distance;
};

inline ExactProjection projectExact(const camera::CameraState& c, glm::dvec3 world) {
    const glm::dvec4 clip = glm::dmat4(c.clipFromRel) * glm::dvec4(world - c.eye, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {(glm::dvec2(ndc) * 0.5 + 0.5) * glm::dvec2(c.width, c.height), ndc.z * 0.5 + 0.5,
            glm::length(world - c.eye)};
}

} // namespace pb::test
