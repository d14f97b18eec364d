#include "gl/DebugOutput.h"

#include <cstdio>
#include <ostream>
#include <sstream>

namespace pb::gl {
namespace {

// Bounded so that a long benchmark with a chatty driver does not grow without limit; errors
// are always kept, they fail tests.
constexpr std::size_t kMaxKeptNonErrors = 1000;
constexpr int kMaxPolledErrors = 32; // glGetError loops forever on a lost context

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* user) {
    std::string text =
        length >= 0 ? std::string(message, static_cast<size_t>(length)) : std::string(message);
    const_cast<DebugOutput*>(static_cast<const DebugOutput*>(user))
        ->record(source, type, id, severity, std::move(text), false);
}

struct DebugEntryPoints {
    PFNGLDEBUGMESSAGECALLBACKPROC callback = nullptr;
    PFNGLDEBUGMESSAGECONTROLPROC control = nullptr;
};

// Core names first (GL 4.3, ES 3.2, or KHR_debug on desktop); ES 3.0/3.1 with KHR_debug only
// has the KHR-suffixed ones. The version is parsed, not read from glad's flags, which are
// stale for the other API when two backends ran in one process.
DebugEntryPoints debugEntryPoints() {
    const GLubyte* v = glGetString(GL_VERSION);
    const std::string version = v ? reinterpret_cast<const char*>(v) : "";
    const bool es = version.rfind("OpenGL ES", 0) == 0;
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const bool core = es ? (major > 3 || (major == 3 && minor >= 2))
                         : (major > 4 || (major == 4 && minor >= 3) || GLAD_GL_KHR_debug);
    if (core && glad_glDebugMessageCallback && glad_glDebugMessageControl)
        return {glad_glDebugMessageCallback, glad_glDebugMessageControl};
    if (es && GLAD_GL_KHR_debug && glad_glDebugMessageCallbackKHR)
        return {glad_glDebugMessageCallbackKHR, glad_glDebugMessageControlKHR};
    return {};
}

std::string hex(unsigned value) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", value);
    return buf;
}

const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
        return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
        return "performance";
    case GL_DEBUG_TYPE_MARKER:
        return "marker";
    default:
        return "other";
    }
}

const char* severityName(GLenum severity) {
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH:
        return "high";
    case GL_DEBUG_SEVERITY_MEDIUM:
        return "medium";
    case GL_DEBUG_SEVERITY_LOW:
        return "low";
    default:
        return "note";
    }
}

} // namespace

std::string glErrorName(GLenum error) {
    switch (error) {
    case GL_NO_ERROR:
        return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW:
        return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
        return "GL_STACK_UNDERFLOW";
    case GL_CONTEXT_LOST:
        return "GL_CONTEXT_LOST";
    default:
        return "GL error " + hex(error);
    }
}

DebugOutput::DebugOutput(Mode mode) {
    // Whatever the context reported before we listened still counts (it lands before a mark
    // taken after construction, and is visible from mark 0).
    poll();
    if (mode == Mode::PollingOnly) return;
    const DebugEntryPoints debug = debugEntryPoints();
    if (!debug.callback) return;
    // Non-debug contexts (OSMesa has no debug flag) only report once this is enabled;
    // synchronous delivery puts the message inside the offending call's stack.
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    debug.control(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    debug.callback(onDebugMessage, this);
    callbackInstalled_ = true;
}

DebugOutput::~DebugOutput() {
    if (!callbackInstalled_) return;
    if (DebugEntryPoints debug = debugEntryPoints(); debug.callback)
        debug.callback(nullptr, nullptr);
}

void DebugOutput::record(GLenum source, GLenum type, GLuint id, GLenum severity, std::string text,
                         bool fromGetError) {
    const bool error = type == GL_DEBUG_TYPE_ERROR;
    const std::uint64_t seq = nextSeq_++;
    if (error && !fromGetError) callbackErrorSincePoll_ = true;
    if (!error && keptNonErrors_ >= kMaxKeptNonErrors) return;
    if (!error) ++keptNonErrors_;
    messages_.push_back({seq, source, type, severity, id, std::move(text), fromGetError});
}

void DebugOutput::poll() {
    for (int i = 0; i < kMaxPolledErrors; ++i) {
        const GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!callbackErrorSincePoll_)
            record(GL_DEBUG_SOURCE_API, GL_DEBUG_TYPE_ERROR, e, GL_DEBUG_SEVERITY_HIGH,
                   "glGetError returned " + glErrorName(e), true);
    }
    callbackErrorSincePoll_ = false;
}

std::uint64_t DebugOutput::mark() {
    poll();
    return nextSeq_;
}

std::vector<DebugMessage> DebugOutput::errorsSince(std::uint64_t mark) {
    poll();
    std::vector<DebugMessage> out;
    for (const DebugMessage& m : messages_)
        if (m.seq >= mark && m.isError()) out.push_back(m);
    return out;
}

std::vector<DebugMessage> DebugOutput::messagesSince(std::uint64_t mark) const {
    std::vector<DebugMessage> out;
    for (const DebugMessage& m : messages_)
        if (m.seq >= mark) out.push_back(m);
    return out;
}

void DebugOutput::discardNonErrors() {
    std::erase_if(messages_, [](const DebugMessage& m) { return !m.isError(); });
    keptNonErrors_ = 0;
}

void DebugOutput::print(std::ostream& out, std::uint64_t mark, bool errorsOnly) {
    out << format(errorsOnly ? errorsSince(mark) : messagesSince(mark));
}

std::string DebugOutput::format(const DebugMessage& m) {
    return std::string(m.fromGetError ? "glGetError" : "KHR_debug") + " " + typeName(m.type) +
           " (" + severityName(m.severity) + ", id " + hex(m.id) + "): " + m.text;
}

std::string DebugOutput::format(const std::vector<DebugMessage>& list) {
    std::ostringstream out;
    for (const DebugMessage& m : list)
        out << format(m) << "\n";
    return out.str();
}

} // namespace pb::gl
