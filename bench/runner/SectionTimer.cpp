#include "SectionTimer.h"

#include "core/Error.h"

#include <glad/gl.h>

#include <algorithm>
#include <ctime>

namespace pb::bench {

TimingChoice chooseTiming(const std::string& requested, const gl::GlCaps& caps,
                          const gl::DriverQuirks& quirks) {
    TimingChoice c;
    auto cpu = [&](const std::string& why) {
        c.method = TimingMethod::CpuFinish;
        c.name = "cpu-finish";
        c.reason = why;
        return c;
    };
    const std::vector<std::string>& names = timingRequestNames();
    if (std::find(names.begin(), names.end(), requested) == names.end())
        throw Error("--timing '" + requested + "': expected auto, cpu, cpu-time or query");
    if (requested == "cpu") return cpu("CPU clock around glFinish per pass (--timing cpu)");
    if (requested == "cpu-time") {
        cpu("process CPU time (all threads) around glFinish per pass (--timing cpu-time)");
        c.processCpuTime = true;
        c.name = "cpu-time";
        return c;
    }
    if (!caps.timerQuery) {
        if (requested == "query")
            throw Error("--timing query: this context has no timer queries "
                        "(EXT_disjoint_timer_query / ARB_timer_query)");
        return cpu("CPU clock around glFinish per pass: the context has no timer queries");
    }
    if (requested == "auto" && quirks.timerQueriesUntrustworthy)
        return cpu("CPU clock around glFinish per pass: timer queries on this driver (" +
                   caps.renderer +
                   ") do not measure execution (DriverQuirks::"
                   "timerQueriesUntrustworthy)");
    c.method = TimingMethod::TimerQuery;
    c.flushBracketed = quirks.timerQueriesNeedFlush;
    c.name = c.flushBracketed ? "timer-query-flush" : "timer-query";
    c.reason = std::string("GL timestamp queries at every pass boundary") +
               (c.flushBracketed ? ", each preceded by glFlush (DriverQuirks::"
                                   "timerQueriesNeedFlush)"
                                 : "") +
               (requested == "query" ? " (--timing query)" : "");
    return c;
}

SectionTimer::SectionTimer(TimingChoice choice, bool es) : choice_(std::move(choice)), es_(es) {}

SectionTimer::~SectionTimer() {
    if (!queries_.empty()) glDeleteQueries(GLsizei(queries_.size()), queries_.data());
}

unsigned SectionTimer::query(size_t i) {
    while (queries_.size() <= i) {
        GLuint q = 0;
        glGenQueries(1, &q);
        queries_.push_back(q);
    }
    return queries_[i];
}

void SectionTimer::mark() {
    Mark m;
    m.owner = open_.empty() ? std::string() : open_.back();
    if (choice_.method == TimingMethod::CpuFinish) {
        glFinish();
        if (choice_.processCpuTime) {
            timespec ts{};
            clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
            m.cpu = std::chrono::steady_clock::time_point(std::chrono::seconds(ts.tv_sec) +
                                                          std::chrono::nanoseconds(ts.tv_nsec));
        } else {
            m.cpu = std::chrono::steady_clock::now();
        }
    } else {
        if (choice_.flushBracketed) glFlush();
        m.query = query(marks_.size());
        if (es_)
            glQueryCounterEXT(m.query, GL_TIMESTAMP_EXT);
        else
            glQueryCounter(m.query, GL_TIMESTAMP);
    }
    marks_.push_back(std::move(m));
}

void SectionTimer::charge(const std::string& section, double ms) {
    if (section.empty()) return;
    for (auto& [name, total] : sections_)
        if (name == section) {
            total += ms;
            return;
        }
    sections_.emplace_back(section, ms);
}

void SectionTimer::beginFrame() {
    open_.clear();
    marks_.clear();
    sections_.clear();
    frameMs_ = 0;
    if (choice_.method == TimingMethod::TimerQuery && es_) {
        GLint disjoint = 0; // reading the flag clears it
        glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
    }
    mark();
}

void SectionTimer::begin(const char* section) {
    open_.emplace_back(section);
    // Opened sections are listed in order even when they take no measurable time.
    charge(section, 0.0);
    mark();
}

void SectionTimer::end(const char* section) {
    if (open_.empty() || open_.back() != section)
        throw Error(std::string("timer: section '") + section + "' closed out of order");
    open_.pop_back();
    mark();
}

bool SectionTimer::endFrame() {
    if (!open_.empty()) throw Error("timer: frame ended with section '" + open_.back() + "' open");
    mark();
    std::vector<double> t(marks_.size(), 0.0); // ms since the first mark
    if (choice_.method == TimingMethod::CpuFinish) {
        for (size_t i = 0; i < marks_.size(); ++i)
            t[i] = std::chrono::duration<double, std::milli>(marks_[i].cpu - marks_[0].cpu).count();
    } else {
        std::vector<GLuint64> ns(marks_.size(), 0);
        for (size_t i = 0; i < marks_.size(); ++i) {
            if (es_)
                glGetQueryObjectui64vEXT(marks_[i].query, GL_QUERY_RESULT_EXT, &ns[i]);
            else
                glGetQueryObjectui64v(marks_[i].query, GL_QUERY_RESULT, &ns[i]);
        }
        for (size_t i = 0; i < marks_.size(); ++i)
            t[i] = double(ns[i] >= ns[0] ? ns[i] - ns[0] : 0) * 1e-6;
        if (es_) {
            GLint disjoint = 0;
            glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
            if (disjoint) return false;
        }
    }
    for (size_t i = 0; i + 1 < marks_.size(); ++i)
        charge(marks_[i].owner, std::max(0.0, t[i + 1] - t[i]));
    frameMs_ = t.back();
    return true;
}

} // namespace pb::bench
