#pragma once
// What the passes of one frame share: the scene, the view, the targets, and results one pass
// hands to the next (the shadow map for the lighting). Passes read settings; they never keep
// per-frame state of their own beyond GPU resources.
#include "gl/DriverQuirks.h"
#include "gl/ProgramCache.h"
#include "gl/Texture.h"
#include "passes/FrameTimer.h"
#include "passes/GBufferLayout.h"
#include "passes/GpuScene.h"
#include "passes/RenderView.h"

#include <glm/glm.hpp>
#include <memory>

namespace pb::render {

struct FrameSettings {
    float exposure = 1.0f; // linear scale before tonemapping
    // The indirect input until the GI passes fill it: a hemispherical ambient, irradiance for
    // an upward normal and for a downward one, blended by the normal's Y.
    glm::vec3 ambientUp{0.0f};
    glm::vec3 ambientDown{0.0f};
    int shadowMapSize = 2048;
    bool indirectOnly = false; // debug view gi_only: the lighting outputs the indirect term
};

// One sun shadow map as the lighting reads it (ShadowPass.h).
struct ShadowMapView {
    const gl::Texture* map = nullptr;
    glm::mat4 fromRel{1.0f}; // camera-relative world -> shadow texture space [0,1]^3
    float texel = 0.0f;      // one texel in texture space
    float normalOffset = 0.0f; // world units: kNormalOffsetTexels texels (ShadowPass.cpp)
    float depthTexel = 0.0f;   // one texel's world size in depth-texture units
    glm::mat3 normalToMap{1.0f}; // world normal -> the receiver plane's normal in texture space
};

struct ShadowResult {
    bool enabled = false;
    ShadowMapView view;  // fitted to what the camera sees
    ShadowMapView scene; // the whole scene: the fallback outside the view map
    // The receiver's share of the depth bias (ShadowPass.cpp, kReceiverBias): x a constant in
    // texels of the map read, y the steepest receiver plane the PCF taps follow.
    glm::vec2 bias{0.0f};
};

// The GI evaluation target the apply pass filled, for the lighting (absent without probes).
struct GiResult {
    bool enabled = false;
    const gl::Texture* irradiance = nullptr; // layout: gi_ddgi_apply.frag
    const gl::Texture* dynamicSh = nullptr;  // gi.dynamic=sh: DynamicShPass::coefficients()
    gl::Defines defines;                     // the profile's GI variant defines + GI_ENABLED
};

// Render targets for one output resolution.
struct FrameTargets {
    FrameTargets(int width, int height);
    GBuffer gbuffer;
    gl::Texture radiance; // RGBA16F linear radiance (lighting output)
    gl::Framebuffer radianceFbo;
    gl::Texture output; // RGBA8 sRGB-encoded tonemapped image
    gl::Framebuffer outputFbo;
    gl::VertexArrayId emptyVao; // core profiles reject draws without a VAO
};

struct FrameContext {
    const GpuScene& scene;
    const RenderView& view;
    const FrameSettings& settings;
    gl::ProgramCache& programs;
    FrameTargets& targets;
    const gl::DriverQuirks& quirks;
    ShadowResult shadow;
    GiResult gi;
    FrameTimer* timer = nullptr; // sections for the bench; null when nobody measures
    // The GBuffer pixel inside each low-resolution GI texel's footprint the apply pass
    // evaluates this frame (GiUpsamplePass::beginFrame; 0 at full resolution).
    glm::ivec2 giJitter{0};
    // gi.guard_exposure: the radiance target (and GI target, SH, probe spheres) hold values x
    // this; the composite divides it out. 1 without the guard.
    float preExposure = 1.0f;
};

// gi.guard_exposure's scale for a frame exposure: 2^trunc(log2(exposure)) - a power of two, so
// scaling and un-scaling are exact in float, and 1 for exposures in (1/2, 2) (frames of usual
// brightness store exactly what they would without the guard). 1 for a non-finite or
// non-positive exposure.
float preExposureScale(float exposure);

class Pass {
public:
    virtual ~Pass() = default;
    virtual const char* name() const = 0;
    virtual void execute(FrameContext& frame) = 0;
};

// Draws the viewport-covering triangle of shaders/fullscreen.vert.
void drawFullscreenTriangle(const FrameTargets& targets);

} // namespace pb::render
