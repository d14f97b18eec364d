#include "WindowFrameTimes.h"

#include "bench/report/Spread.h"

#include <cstdio>
#include <numeric>

namespace pb::bench {

void WindowFrameTimes::framePresented() {
    const auto now = std::chrono::steady_clock::now();
    // From the first frame's present on: the first interval would include shader compiles.
    if (presented_++ > 0) ms_.push_back(std::chrono::duration<double, std::milli>(now - last_).count());
    last_ = now;
}

std::string WindowFrameTimes::summary() const {
    if (ms_.empty())
        return "window: " + std::to_string(presented_) +
               " frame(s) shown, too few for frame times (the first compiles shaders)";
    const double mean = std::accumulate(ms_.begin(), ms_.end(), 0.0) / double(ms_.size());
    char line[256];
    std::snprintf(line, sizeof line,
                  "window: %zu frames, frame time p50 %.2f ms, p90 %.2f ms, p99 %.2f ms, mean "
                  "%.2f ms (%.1f fps); the first frame (shaders) not counted",
                  ms_.size(), bench::percentile(ms_, 0.5), bench::percentile(ms_, 0.9),
                  bench::percentile(ms_, 0.99), mean, mean > 0 ? 1000.0 / mean : 0.0);
    return line;
}

} // namespace pb::bench
