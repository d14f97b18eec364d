#include "gl/DebugLabels.h"

#include <algorithm>
#include <vector>

namespace pb::gl {

constexpr std::size_t kMaxLabel = 255; // below the smallest GL_MAX_LABEL_LENGTH (256)

// The core name where the loader found it (GL 4.3, ES 3.2), else the KHR one (ES 3.0/3.1 with
// KHR_debug). Looked up at each call: the loader's pointers are those of the current
// backend, and a process may run two (tests do).
void pushDebugGroup(const char* name) {
    if (glad_glPushDebugGroup)
        glad_glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
    else if (glad_glPushDebugGroupKHR)
        glad_glPushDebugGroupKHR(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}

void popDebugGroup() {
    if (glad_glPopDebugGroup)
        glad_glPopDebugGroup();
    else if (glad_glPopDebugGroupKHR)
        glad_glPopDebugGroupKHR();
}

void labelObject(GLenum identifier, GLuint name, const std::string& label) {
    if (name == 0 || label.empty()) return;
    // GL_MAX_LABEL_LENGTH is at least 256 and a label must be shorter (else
    // GL_INVALID_VALUE): a program's label with its defines can be longer.
    const GLsizei length = GLsizei(std::min<std::size_t>(label.size(), kMaxLabel));
    if (glad_glObjectLabel)
        glad_glObjectLabel(identifier, name, length, label.data());
    else if (glad_glObjectLabelKHR)
        glad_glObjectLabelKHR(identifier, name, length, label.data());
}

std::string objectLabel(GLenum identifier, GLuint name) {
    std::vector<char> buf(256, '\0');
    GLsizei length = 0;
    if (glad_glGetObjectLabel)
        glad_glGetObjectLabel(identifier, name, GLsizei(buf.size()), &length, buf.data());
    else if (glad_glGetObjectLabelKHR)
        glad_glGetObjectLabelKHR(identifier, name, GLsizei(buf.size()), &length, buf.data());
    return std::string(buf.data(), std::size_t(length > 0 ? length : 0));
}

} // namespace pb::gl
