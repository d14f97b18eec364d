#pragma once
// Sun shadow map: one orthographic depth map fitted to the scene's bounds. Skipped (and no
// texture allocated) when the sun is off.
#include "passes/FrameContext.h"

namespace pb::render {

class ShadowPass : public Pass {
public:
    const char* name() const override { return "shadow"; }
    void execute(FrameContext& frame) override;

private:
    std::unique_ptr<gl::Texture> map_;
    std::unique_ptr<gl::Framebuffer> fbo_;
};

} // namespace pb::render
