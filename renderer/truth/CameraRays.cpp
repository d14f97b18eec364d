#include "truth/CameraRays.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>

namespace pb::truth {

CameraRays::CameraRays(const scene::View& view, int width, int height)
    : width_(std::max(1, width)), height_(std::max(1, height)) {
    glm::dvec3 dir = glm::dvec3(view.target) - glm::dvec3(view.position);
    if (glm::length(dir) <= 0.0 || !std::isfinite(glm::length(dir)))
        throw Error("camera '" + view.name + "': position and target coincide");
    glm::dvec3 f = glm::normalize(dir);
    glm::dvec3 up = std::abs(f.y) > 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    glm::dvec3 s = glm::normalize(glm::cross(f, up)); // glm::lookAt's side and up vectors
    glm::dvec3 u = glm::cross(s, f);
    eye_ = view.position;
    forward_ = glm::vec3(f);
    right_ = glm::vec3(s);
    up_ = glm::vec3(u);
    tanHalfY_ = float(std::tan(glm::radians(double(view.fovYDegrees)) * 0.5));
    aspect_ = float(width_) / float(height_);
}

glm::vec3 CameraRays::direction(int x, int y, float jx, float jy) const {
    float ndcX = 2.0f * (float(x) + jx) / float(width_) - 1.0f;
    float ndcY = 1.0f - 2.0f * (float(y) + jy) / float(height_);
    return glm::normalize(forward_ + right_ * (ndcX * tanHalfY_ * aspect_) + up_ * (ndcY * tanHalfY_));
}

} // namespace pb::truth
