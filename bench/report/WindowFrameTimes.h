#pragma once
// What the window mode (`render --platform glfw`) prints when it closes, as glmark2 does: the
// frame-to-frame times it showed, as percentiles (issue 25, item 10). The first frame compiles
// shaders and is not counted. Wall-clock times of this device, for people; not a benchmark
// (`probebench bench` interleaves and measures).
#include <chrono>
#include <string>
#include <vector>

namespace pb::bench {

class WindowFrameTimes {
public:
    // Call after each frame is presented (swapped).
    void framePresented();
    // "window: 120 frames, frame time p50 8.31 ms, p90 9.02 ms, p99 11.40 ms, mean 8.45 ms
    // (118.3 fps); the first frame (shaders) not counted", or why there is nothing to say.
    std::string summary() const;
    const std::vector<double>& milliseconds() const { return ms_; }

private:
    std::vector<double> ms_;
    std::chrono::steady_clock::time_point last_;
    int presented_ = 0;
};

} // namespace pb::bench
