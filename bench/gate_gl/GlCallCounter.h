#pragma once
// Counts the GL calls a frame makes, per FrameTimer section (pass), on the GL side: while a
// counter exists, the loader's function pointers of the calls below point at counting shims
// that forward to the driver, so every draw and bind the real passes issue is seen - whatever
// file it comes from - without a hook in any pass. Installed only for the gate's counting
// frame (never while timing); one counter at a time, on the thread that owns the context.
//   draws:       glDrawArrays/Elements (+Instanced, RangeElements)
//   programs:    glUseProgram with a program (0 = unbind, not counted)
//   tex_binds:   glBindTexture with a texture;  tex_unbinds: with 0
//   clears:      glClear and glClearBuffer*
//   fbo_binds:   glBindFramebuffer (any target, 0 included)
#include "passes/FrameTimer.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pb::gate {

struct GlCallCounts {
    std::int64_t draws = 0, programs = 0, texBinds = 0, texUnbinds = 0, clears = 0, fboBinds = 0;
    bool operator==(const GlCallCounts&) const = default;
};

class GlCallCounter : public render::FrameTimer {
public:
    GlCallCounter(); // throws pb::Error if another counter is installed
    ~GlCallCounter() override;
    GlCallCounter(const GlCallCounter&) = delete;
    GlCallCounter& operator=(const GlCallCounter&) = delete;

    void begin(const char* section) override;
    void end(const char* section) override;

    // Exclusive counts per section in first-opened order; calls outside every section go to
    // "frame" (first).
    const std::vector<std::pair<std::string, GlCallCounts>>& sections() const { return sections_; }
    GlCallCounts& current(); // the innermost open section's counts (used by the shims)

private:
    std::vector<std::pair<std::string, GlCallCounts>> sections_;
    std::vector<size_t> open_;
};

} // namespace pb::gate
