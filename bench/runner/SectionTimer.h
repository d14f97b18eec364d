#pragma once
// The bench's FrameTimer: exclusive time per section (pass) of one frame, by one of two
// methods chosen per driver (chooseTiming):
//   cpu-finish:  glFinish + steady_clock at every section boundary - the truth on a software
//                rasterizer (DriverQuirks::timerQueriesUntrustworthy), and a fallback anywhere;
//                the per-pass glFinish serialises CPU and GPU, which the numbers then include.
//   cpu-time:    glFinish + the process's CPU time (all threads, CLOCK_PROCESS_CPUTIME_ID):
//                on a software rasterizer the work the pass cost in CPU-ms, which other
//                processes on a shared machine barely disturb (they steal wall time, not this
//                process's CPU time); not a frame time (llvmpipe's threads add up).
//   timer-query: GL timestamps (glQueryCounter) at every boundary, read after the frame; on
//                drivers with DriverQuirks::timerQueriesNeedFlush each boundary is preceded by
//                glFlush (DESIGN.md: llvmpipe's queries match wall time only then).
// Time between two boundaries goes to the innermost open section, so nested sections
// ("gi-fill" inside "gi-apply") are exclusive and sum, with the gaps, to the frame.
#include "gl/Capabilities.h"
#include "gl/DriverQuirks.h"
#include "passes/FrameTimer.h"

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pb::bench {

enum class TimingMethod { CpuFinish, TimerQuery };

struct TimingChoice {
    TimingMethod method = TimingMethod::CpuFinish;
    bool flushBracketed = false; // timer queries with glFlush before each boundary
    bool processCpuTime = false; // CpuFinish: process CPU time instead of wall time
    std::string name;            // "cpu-finish" | "cpu-time" | "timer-query" | "timer-query-flush"
    std::string reason;          // one line: why this method on this driver
};

// The names --timing takes, for the command lines to check before any work.
inline const std::vector<std::string>& timingRequestNames() {
    static const std::vector<std::string> names{"auto", "cpu", "cpu-time", "query"};
    return names;
}

// requested: one of timingRequestNames(): "auto" (queries where the driver's are trustworthy,
// else cpu), "cpu", "cpu-time" or "query". Throws pb::Error for "query" on a context without
// timer queries, or an unknown name.
TimingChoice chooseTiming(const std::string& requested, const gl::GlCaps& caps,
                          const gl::DriverQuirks& quirks);

class SectionTimer : public render::FrameTimer {
public:
    explicit SectionTimer(TimingChoice choice, bool es);
    ~SectionTimer() override;
    SectionTimer(const SectionTimer&) = delete;
    SectionTimer& operator=(const SectionTimer&) = delete;

    void beginFrame();
    // Closes the frame and resolves its times. False when the GPU reported a disjoint event
    // (timer queries only): the frame's times are meaningless and should be taken again.
    bool endFrame();
    void begin(const char* section) override;
    void end(const char* section) override;

    // The last frame: exclusive ms per section in first-opened order, and the whole frame.
    const std::vector<std::pair<std::string, double>>& sections() const { return sections_; }
    double frameMs() const { return frameMs_; }

private:
    struct Mark {
        unsigned query = 0; // timer-query
        std::chrono::steady_clock::time_point cpu;
        std::string owner; // the section the interval after this mark belongs to ("" = none)
    };
    void mark();
    void charge(const std::string& section, double ms);
    unsigned query(size_t i);

    TimingChoice choice_;
    bool es_;
    std::vector<std::string> open_;
    std::vector<Mark> marks_;
    std::vector<unsigned> queries_; // pool, grown on demand
    std::vector<std::pair<std::string, double>> sections_;
    double frameMs_ = 0;
};

} // namespace pb::bench
