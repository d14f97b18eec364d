#pragma once
// gi.dynamic=sh: each dynamic object's irradiance as an L1 spherical-harmonics fit, computed
// on the GPU once per frame before the lighting (the talk: "fire dynamic object SH
// calculation early in the frame"), from the same DDGI data and the same lookup the apply
// pass runs: gi_ddgi_points.frag evaluates common_ddgi.glsl at the object's centre for
// kDirections normals (spherical Fibonacci, view = normal), one draw per volume like the apply
// pass; gi_dynamic_sh_project.frag fits 1, x, y, z to them by least squares (weights solved
// on the CPU once: exact for any field that is linear in the normal, the L1 SH projection for
// evenly spread directions). On the GPU rather than from the CPU sampler because the GPU holds
// the probe data as the frame uses it (BC6H, fp16 variant, gi.volume_lod's kept volumes), and
// so the pass costs frame time where the benchmark can see it.
// The lighting reads the coefficients (FrameContext::gi.dynamicSh) for pixels whose GBuffer
// flags mark a dynamic object; the apply pass skips those pixels.
#include "passes/DynamicObjects.h"
#include "passes/FrameContext.h"
#include "passes/GpuProbes.h"
#include "profile/Profile.h"

#include <memory>

namespace pb::render {

class DynamicShPass : public Pass {
public:
    static constexpr int kDirections = 64;

    // Throws pb::Error when the scene has more dynamic objects than the flags can number.
    DynamicShPass(const GpuProbes& probes, const profile::Profile& profile,
                  const scene::Scene& scene);
    const char* name() const override { return "gi-dynamic-sh"; }
    void execute(FrameContext& frame) override;

    // Texel (k, o): coefficient k (of 1, n.x, n.y, n.z) of object o; rgb = E * fade, a = fade.
    const gl::Texture& coefficients() const { return coefficients_; }
    const DynamicObjects& objects() const { return objects_; }
    std::size_t bytes() const; // GPU memory of its textures

private:
    const GpuProbes& probes_;
    gl::Defines defines_;
    DynamicObjects objects_;
    int rows_;                           // max(1, objects)
    gl::Texture directions_;             // kDirections x rows: normal = view
    gl::Texture positions_;              // kDirections x rows: centre, camera-relative
    gl::Texture weights_;                // kDirections x 1: least-squares weights
    gl::Texture lookups_, coefficients_; // RGBA32F
    gl::Framebuffer lookupFbo_, coefficientFbo_;
};

// The least-squares weights: coefficient k = sum_i weights[i][k] * f(direction i).
std::vector<glm::vec4> shFitWeights(const std::vector<glm::vec3>& directions);

} // namespace pb::render
