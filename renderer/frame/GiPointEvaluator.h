#pragma once
// Evaluates the GPU DDGI lookup at arbitrary world points (not at GBuffer pixels): each point
// is one texel of a target; gi_ddgi_points.frag reads its position, normal and view from
// RGBA32F textures and runs common_ddgi.glsl, the code the apply pass runs, with the same
// per-volume draws. For the CPU/GPU cross-check and accuracy tools. Requires a current context.
#include "gl/ProgramCache.h"
#include "passes/GpuProbes.h"
#include "profile/Profile.h"

#include <glm/glm.hpp>
#include <vector>

namespace pb::render {

struct GiPoint {
    glm::vec3 position{0.0f}; // world
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec3 view{0.0f, 1.0f, 0.0f}; // surface -> viewer
};

class GiPointEvaluator {
public:
    // Uses the profile's shader variant (loops, order, ...) and target format.
    GiPointEvaluator(const GpuProbes& probes, const profile::Profile& profile,
                     gl::ProgramCache& programs);
    // Per point: rgb = E * fade, a = weight (0 outside every volume), as the CPU sampler's
    // IrradianceSample. `width` = points per row of the target.
    std::vector<glm::vec4> evaluate(const std::vector<GiPoint>& points, int width = 100);

private:
    const GpuProbes& probes_;
    profile::Profile profile_;
    gl::ProgramCache& programs_;
    gl::VertexArrayId vao_;
};

} // namespace pb::render
