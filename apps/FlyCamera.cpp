#include "FlyCamera.h"

#include <algorithm>
#include <cmath>

namespace pb::app {

FlyCamera::FlyCamera(const scene::View& start, const scene::Bounds& b)
    : position_(start.position), fovY_(start.fovYDegrees) {
    glm::dvec3 d = glm::normalize(glm::dvec3(start.target) - glm::dvec3(start.position));
    yaw_ = std::atan2(d.x, -d.z);
    pitch_ = std::asin(std::clamp(d.y, -1.0, 1.0));
    speed_ = std::max(0.25 * glm::length(glm::dvec3(b.size())), 0.5) / 4.0;
}

void FlyCamera::update(const platform::InputState& in, double dt) {
    const double look = 0.003; // radians per pixel dragged
    yaw_ += in.mouseDx * look;
    pitch_ = std::clamp(pitch_ - in.mouseDy * look, -1.5, 1.5);
    glm::dvec3 fwd(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_),
                   -std::cos(yaw_) * std::cos(pitch_));
    glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::dvec3(0, 1, 0)));
    glm::dvec3 move(0.0);
    if (in.forward) move += fwd;
    if (in.back) move -= fwd;
    if (in.right) move += right;
    if (in.left) move -= right;
    if (in.up) move.y += 1;
    if (in.down) move.y -= 1;
    if (glm::length(move) > 0)
        position_ += glm::normalize(move) * speed_ * (in.fast ? 4.0 : 1.0) * dt;
}

scene::View FlyCamera::view() const {
    glm::dvec3 fwd(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_),
                   -std::cos(yaw_) * std::cos(pitch_));
    scene::View v;
    v.name = "fly";
    v.position = glm::vec3(position_);
    // A far target keeps the direction accurate in float when the eye is far from the origin.
    v.target = glm::vec3(position_ + fwd * 1000.0);
    v.fovYDegrees = fovY_;
    return v;
}

} // namespace pb::app
