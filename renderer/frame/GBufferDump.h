#pragma once
// --dump-gbuffer: every channel of the GBuffer table as a viewable file.
#include "gl/ProgramCache.h"
#include "passes/FrameContext.h"

#include <string>

namespace pb::render {

void writeGBufferDump(const std::string& dir, FrameTargets& targets, const RenderView& view,
                      gl::ProgramCache& programs);

} // namespace pb::render
