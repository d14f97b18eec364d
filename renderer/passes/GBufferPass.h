#pragma once
// Fills the GBuffer channels and depth from the scene's instances.
#include "passes/DynamicObjects.h"
#include "passes/FrameContext.h"

namespace pb::render {

class GBufferPass : public Pass {
public:
    const char* name() const override { return "gbuffer"; }
    void execute(FrameContext& frame) override;

private:
    const scene::Scene* objectsOf_ = nullptr; // the scene dynamic_ was computed for
    DynamicObjects dynamic_;
};

} // namespace pb::render
