#pragma once
// Names a GL capture can show (issue 25, item 10): debug groups around each pass and labels
// on the main textures, framebuffers and programs, so RenderDoc, Nsight or apitrace list
// "gbuffer", "gi-apply", "probes kitchen irradiance" instead of anonymous calls and ids.
//
// On in every context, debug or not: a capture tool records the application's own context,
// which is a non-debug one when the bench or the gate times frames. glPushDebugGroup and
// glObjectLabel are core in GL 4.3 and ES 3.2 (KHR_debug before); where neither entry point
// is loaded the calls do nothing. They cost a few calls per pass, no draws or binds, so the
// gate's GL call counts (bench/gate_gl/GlCallCounter.h) do not see them.
#include "gl/GlObject.h"

#include <string>

namespace pb::gl {

// glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, name) / glPopDebugGroup, core or KHR.
void pushDebugGroup(const char* name);
void popDebugGroup();

// glObjectLabel: `identifier` is GL_TEXTURE, GL_FRAMEBUFFER, GL_PROGRAM, GL_BUFFER, ...
void labelObject(GLenum identifier, GLuint name, const std::string& label);

// glGetObjectLabel; "" where the entry point is missing (tests read labels back with it).
std::string objectLabel(GLenum identifier, GLuint name);

// RAII group; nests.
class DebugGroup {
public:
    explicit DebugGroup(const char* name) { pushDebugGroup(name); }
    ~DebugGroup() { popDebugGroup(); }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

} // namespace pb::gl
