#pragma once
// Debug views probes_irradiance / probes_visibility: after the lighting, a sphere per probe of
// every loaded volume is drawn into the radiance target, depth-tested (and written) against the
// GBuffer's depth, so walls hide the probes behind them. Shaders: debug_probe_sphere.*.
#include "passes/FrameContext.h"
#include "passes/GpuProbes.h"

#include <memory>

namespace pb::render {

class ProbeDebugPass : public Pass {
public:
    ProbeDebugPass(const GpuProbes& probes, bool visibility);
    const char* name() const override { return "debug-probes"; }
    void execute(FrameContext& frame) override;

private:
    const GpuProbes& probes_;
    bool visibility_;
    // The targets fbo_ was made for: FrameRenderer allocates new targets while the old ones
    // still exist, so a new set never has the address of the one cached here.
    const FrameTargets* fboFor_ = nullptr;
    std::unique_ptr<gl::Framebuffer> fbo_; // radiance + the GBuffer's depth
};

} // namespace pb::render
