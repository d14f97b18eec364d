#pragma once
// The interactive fly camera of the glfw window: WASD moves, Q/E down/up, Shift is faster,
// dragging with the left mouse button looks around. Speed scales with the scene size.
#include "platforms/Platform.h"
#include "scene/Scene.h"

namespace pb::app {

class FlyCamera {
public:
    FlyCamera(const scene::View& start, const scene::Bounds& sceneBounds);
    void update(const platform::InputState& input, double dtSeconds);
    scene::View view() const;

private:
    glm::dvec3 position_;
    double yaw_ = 0, pitch_ = 0; // radians
    double speed_;               // units per second
    float fovY_;
};

} // namespace pb::app
