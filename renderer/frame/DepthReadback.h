#pragma once
// The GBuffer depth read back as floats (GLES cannot glReadPixels a depth texture): one draw of
// shaders/debug_depth_copy.frag into an RGBA32F target. Rows top to bottom; channel 0 = the
// distance from the eye (0 on sky), channel 1 = the window depth in [0, 1].
#include "gl/ProgramCache.h"
#include "image/Image.h"
#include "passes/FrameContext.h"

namespace pb::render {

image::ImageF readDepthDistance(const FrameTargets& targets, const RenderView& view,
                                gl::ProgramCache& programs);

} // namespace pb::render
