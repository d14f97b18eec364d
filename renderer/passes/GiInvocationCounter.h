#pragma once
// Diagnostics of the GI apply pass: fragment-shader invocations per draw, counted by the
// shaders themselves (common_gi_invocations.glsl: an atomic counter, GLSL ES 3.10) into one
// small buffer of `slots` counters. Unlike the "evaluated" attachment, which shows what a draw
// wrote, this counts what the device shaded - discarded invocations included.
#include "gl/GlObject.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pb::render {

class GiInvocationCounter {
public:
    // Whether the current context can count: OpenGL ES 3.1+ (or desktop 4.5, which takes
    // GLSL ES 3.10) with GL_MAX_FRAGMENT_ATOMIC_COUNTERS > 0. Empty when it can, else why not
    // ("not counted: ..."). Queried once per counter object.
    const std::string& unsupportedReason();
    bool supported() { return unsupportedReason().empty(); }

    void reset(int slots);                  // zeroes `slots` counters (creates the buffer)
    void bind(int slot) const;              // binding 0 = counter `slot` for the next draws
    std::vector<std::int64_t> read() const; // waits for the draws; one value per slot

private:
    bool queried_ = false;
    std::string reason_;
    gl::BufferId buffer_;
    int slots_ = 0;
};

} // namespace pb::render
