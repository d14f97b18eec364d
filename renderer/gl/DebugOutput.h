#pragma once
// Collects what the GL reports about misuse: KHR_debug messages through a callback where the
// context has it, plus glGetError polling (always, as the fallback and the cross-check).
// Tests treat every recorded error as a failure: take a mark, run GL code, ask errorsSince.
//
// One DebugOutput per context, created and destroyed while that context is current, and
// destroyed before the context (it unregisters its callback).
#include <glad/gl.h>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace pb::gl {

struct DebugMessage {
    std::uint64_t seq = 0; // position in the stream of everything recorded
    GLenum source = 0, type = 0, severity = 0;
    GLuint id = 0;
    std::string text;
    bool fromGetError = false; // polled with glGetError rather than delivered by KHR_debug

    bool isError() const { return type == GL_DEBUG_TYPE_ERROR; }
};

class DebugOutput {
public:
    enum class Mode { CallbackAndPolling, PollingOnly };

    explicit DebugOutput(Mode mode = Mode::CallbackAndPolling);
    ~DebugOutput();
    DebugOutput(const DebugOutput&) = delete;
    DebugOutput& operator=(const DebugOutput&) = delete;

    bool callbackInstalled() const { return callbackInstalled_; }

    // Polls glGetError, then returns the sequence number the next message will get: errors
    // already pending belong before the mark.
    std::uint64_t mark();

    // Errors (KHR_debug type ERROR or glGetError codes) recorded at or after `mark`; polls first.
    std::vector<DebugMessage> errorsSince(std::uint64_t mark);
    std::size_t errorCountSince(std::uint64_t mark) { return errorsSince(mark).size(); }

    // Every message at or after `mark` still kept (non-errors are capped, errors are not).
    std::vector<DebugMessage> messagesSince(std::uint64_t mark) const;

    // Records pending glGetError codes. Skipped codes: when the callback already delivered an
    // error since the last poll, glGetError returns the same error again and is not repeated.
    void poll();

    // Forgets every non-error message recorded so far (errors stay: they fail tests). For a
    // reader that consumes informational messages as they come (driver statistics), so that
    // the cap on kept non-errors applies per batch, not per process.
    void discardNonErrors();

    void print(std::ostream& out, std::uint64_t mark, bool errorsOnly = true);

    static std::string format(const DebugMessage& m);                 // one line
    static std::string format(const std::vector<DebugMessage>& list); // one line each

    // Called by the GL; public only so the C callback can reach it.
    void record(GLenum source, GLenum type, GLuint id, GLenum severity, std::string text,
                bool fromGetError);

private:
    std::vector<DebugMessage> messages_;
    std::uint64_t nextSeq_ = 0;
    std::size_t keptNonErrors_ = 0;
    bool callbackInstalled_ = false;
    bool callbackErrorSincePoll_ = false;
};

// "GL_INVALID_ENUM" for a glGetError code.
std::string glErrorName(GLenum error);

} // namespace pb::gl
