#pragma once
// Exposure, tonemap and sRGB encoding of the radiance target into the 8-bit output.
#include "passes/FrameContext.h"

namespace pb::render {

class CompositePass : public Pass {
public:
    const char* name() const override { return "composite"; }
    void execute(FrameContext& frame) override;
};

} // namespace pb::render
