#pragma once
// Camera matrices for one frame. Rendering is camera-relative: the eye sits at the origin of
// the "rel" space (world axes, world units), and every local->rel matrix is composed in double
// precision on the CPU, so scenes 1e6 units from the origin keep float precision on the GPU.
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace pb::render {

struct RenderView {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0, 0, -1};
    int width = 1, height = 1;
    float fovYDegrees = 60.0f;
    float nearPlane = 0.01f, farPlane = 100.0f;
    glm::mat4 clipFromRel{1.0f};   // projection * rotation-only view
    glm::mat4 relFromClip{1.0f};

    // local -> rel for an instance transform (double precision, then rounded to float).
    glm::mat4 relFromLocal(const glm::mat4& worldFromLocal) const;
    glm::vec3 toRel(const glm::vec3& world) const { return glm::vec3(glm::dvec3(world) - eye); }
};

// Builds the view; near/far are fitted to `bounds` (the scene) so depth precision follows the
// scene's scale. Throws pb::Error for a degenerate camera (position == target).
RenderView makeRenderView(const scene::View& view, const scene::Bounds& bounds, int width,
                          int height);

} // namespace pb::render
