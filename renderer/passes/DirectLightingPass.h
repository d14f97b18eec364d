#pragma once
// Deferred lighting into the linear radiance target: sun with shadows, punctual lights,
// emissive, and albedo x indirect irradiance (the GI target blended with the ambient by its
// weight when the GI apply pass ran, else the ambient alone).
#include "passes/FrameContext.h"

namespace pb::render {

class DirectLightingPass : public Pass {
public:
    const char* name() const override { return "direct"; }
    void execute(FrameContext& frame) override;
    static constexpr int kMaxLights = 16; // must match MAX_LIGHTS in lighting_direct.frag
};

} // namespace pb::render
