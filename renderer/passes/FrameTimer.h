#pragma once
// The seam through which a benchmark measures named sections of a frame. FrameRenderer opens
// one section per pass (named by Pass::name()); a pass may open sub-sections inside its own
// (e.g. "gi-fill" inside "gi-apply" for the stencil mark of each volume). A timer attributes
// time to the innermost open section (exclusive time), so sections nest but never overlap.
// Rendering without a timer (null) costs nothing. How time is taken (CPU clock around
// glFinish, timer queries, ...) is the timer's business, not the renderer's.
//
// Each section is also a GL debug group of the same name (gl/DebugLabels.h), timer or not, so
// a capture shows the passes; the group opens before the timer's begin and closes after its
// end, outside the timed interval.
#include "gl/DebugLabels.h"

namespace pb::render {

class FrameTimer {
public:
    virtual ~FrameTimer() = default;
    virtual void begin(const char* section) = 0;
    virtual void end(const char* section) = 0;
};

// RAII section; a null timer makes it a no-op.
class TimedSection {
public:
    TimedSection(FrameTimer* timer, const char* section)
        : group_(section), timer_(timer), section_(section) {
        if (timer_) timer_->begin(section_);
    }
    ~TimedSection() {
        if (timer_) timer_->end(section_);
    }
    TimedSection(const TimedSection&) = delete;
    TimedSection& operator=(const TimedSection&) = delete;

private:
    gl::DebugGroup group_; // first: pushed before the timer begins, popped after it ends
    FrameTimer* timer_;
    const char* section_;
};

} // namespace pb::render
