#pragma once
// The stress sweep's renderer on the current GL context: one FrameRenderer per frame (the
// profile shapes the passes at construction), the case's probes in the variant's storage
// format, the radiance and the GI target read back. A GL error during a frame is a pb::Error
// (the run reports it), never a silent wrong frame.
#include "gl/DebugOutput.h"
#include "probes/StorageFormat.h"
#include "stress/StressSweep.h"

#include <map>

namespace pb::stress {

class GlStressRenderer : public StressRenderer {
public:
    explicit GlStressRenderer(gl::DebugOutput& debug) : debug_(debug) {}
    RenderedFrame render(const CaseData& data, const StressVariant& variant) override;
    // Also read the tonemapped 8-bit image (RenderedFrame::output; --images). Off by default:
    // at 4096x4096 every read-back costs seconds on llvmpipe.
    void setReadOutput(bool on) { readOutput_ = on; }

private:
    const probes::ProbeSet& probesFor(const CaseData& data, probes::StorageFormat f);

    gl::DebugOutput& debug_;
    bool readOutput_ = false;
    std::uint64_t cached_ = 0; // CaseData::id the stored sets below belong to
    std::map<probes::StorageFormat, probes::ProbeSet> sets_;
};

// The largest square the sweep renders: min(limit, GL_MAX_RENDERBUFFER_SIZE,
// GL_MAX_TEXTURE_SIZE) of the current context.
int largestStressResolution(int limit = 4096);

} // namespace pb::stress
