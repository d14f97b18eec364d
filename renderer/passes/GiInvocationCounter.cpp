#include "passes/GiInvocationCounter.h"

#include "core/Error.h"

#include <cstring>
#include <string_view>

namespace pb::render {

const std::string& GiInvocationCounter::unsupportedReason() {
    if (queried_) return reason_;
    queried_ = true;
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const bool es = version && std::string_view(version).find("OpenGL ES") != std::string::npos;
    const bool ok =
        es ? (major > 3 || (major == 3 && minor >= 1)) : (major > 4 || (major == 4 && minor >= 5));
    if (!ok) {
        reason_ = "not counted: atomic counters need OpenGL ES 3.1 (context " +
                  std::to_string(major) + "." + std::to_string(minor) + ")";
        return reason_;
    }
    GLint counters = 0, buffers = 0;
    glGetIntegerv(GL_MAX_FRAGMENT_ATOMIC_COUNTERS, &counters);
    glGetIntegerv(GL_MAX_FRAGMENT_ATOMIC_COUNTER_BUFFERS, &buffers);
    if (counters < 1 || buffers < 1)
        reason_ = "not counted: GL_MAX_FRAGMENT_ATOMIC_COUNTERS = " + std::to_string(counters) +
                  ", GL_MAX_FRAGMENT_ATOMIC_COUNTER_BUFFERS = " + std::to_string(buffers);
    return reason_;
}

void GiInvocationCounter::reset(int slots) {
    if (!buffer_) {
        GLuint id = 0;
        glGenBuffers(1, &id);
        buffer_ = gl::BufferId(id);
    }
    const std::vector<GLuint> zero(size_t(slots), 0u);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, buffer_.id());
    if (slots != slots_)
        glBufferData(GL_ATOMIC_COUNTER_BUFFER, GLsizeiptr(zero.size() * sizeof(GLuint)),
                     zero.data(), GL_DYNAMIC_READ);
    else
        glBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, GLsizeiptr(zero.size() * sizeof(GLuint)),
                        zero.data());
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
    slots_ = slots;
}

void GiInvocationCounter::bind(int slot) const {
    glBindBufferRange(GL_ATOMIC_COUNTER_BUFFER, 0, buffer_.id(), GLintptr(slot * sizeof(GLuint)),
                      GLsizeiptr(sizeof(GLuint)));
}

std::vector<std::int64_t> GiInvocationCounter::read() const {
    // The shaders' atomic writes must be visible to the mapping below.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    std::vector<std::int64_t> values(size_t(slots_), 0);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, buffer_.id());
    const auto* p = static_cast<const GLuint*>(glMapBufferRange(
        GL_ATOMIC_COUNTER_BUFFER, 0, GLsizeiptr(size_t(slots_) * sizeof(GLuint)), GL_MAP_READ_BIT));
    if (!p) {
        glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
        throw Error("gi apply: could not map the invocation counters");
    }
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = std::int64_t(p[i]);
    glUnmapBuffer(GL_ATOMIC_COUNTER_BUFFER);
    glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, 0);
    return values;
}

} // namespace pb::render
