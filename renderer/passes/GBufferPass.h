#pragma once
// Fills the GBuffer channels and depth from the scene's instances.
#include "passes/FrameContext.h"

namespace pb::render {

class GBufferPass : public Pass {
public:
    const char* name() const override { return "gbuffer"; }
    void execute(FrameContext& frame) override;
};

} // namespace pb::render
