#include "respond/ResponseMetrics.h"

#include <algorithm>
#include <cmath>

namespace pb::respond {

double meanAbsError(const LumaImage& image, const LumaImage& reference) {
    if (image.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < image.size(); ++i)
        sum += std::fabs(double(image[i]) - double(reference[i]));
    return sum / double(image.size());
}

int settleFrame(const std::vector<double>& relativeError, double tolerance) {
    int frame = -1;
    for (int n = int(relativeError.size()) - 1; n >= 0; --n) {
        if (!(relativeError[std::size_t(n)] <= tolerance)) break;
        frame = n;
    }
    return frame;
}

double overshoot(const std::vector<LumaImage>& frames, const LumaImage& reference) {
    if (frames.empty()) return 0.0;
    const LumaImage& first = frames.front();
    double stepSq = 0.0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        const double d = double(first[i]) - reference[i];
        stepSq += d * d;
    }
    if (stepSq <= 0.0) return 0.0;
    double worst = 0.0;
    for (const LumaImage& f : frames) {
        double along = 0.0;
        for (std::size_t i = 0; i < f.size(); ++i)
            along += (double(f[i]) - reference[i]) * (double(first[i]) - reference[i]);
        worst = std::max(worst, -along / stepSq);
    }
    return worst;
}

double flicker(const std::vector<LumaImage>& frames, std::size_t window) {
    if (frames.empty() || window < 2) return 0.0;
    const std::size_t n = std::min(window, frames.size());
    const std::size_t first = frames.size() - n;
    double sum = 0.0;
    std::size_t counted = 0;
    for (std::size_t px = 0; px < frames.back().size(); ++px) {
        double s = 0.0, s2 = 0.0;
        for (std::size_t f = first; f < frames.size(); ++f) {
            s += frames[f][px];
            s2 += double(frames[f][px]) * frames[f][px];
        }
        const double mean = s / double(n);
        if (!(mean > 0.0)) continue;
        const double var = std::max(0.0, s2 / double(n) - mean * mean);
        sum += std::sqrt(var) / mean;
        ++counted;
    }
    return counted ? sum / double(counted) : 0.0;
}

FarDrift farDrift(const std::vector<LumaImage>& frames, const std::vector<bool>& far) {
    FarDrift out;
    if (frames.empty()) return out;
    const LumaImage& first = frames.front();
    double base = 0.0;
    for (std::size_t i = 0; i < first.size(); ++i)
        if (far[i]) {
            base += first[i];
            ++out.pixels;
        }
    if (!(base > 0.0)) return out;
    for (const LumaImage& f : frames) {
        double moved = 0.0;
        for (std::size_t i = 0; i < f.size(); ++i)
            if (far[i]) moved += std::fabs(double(f[i]) - first[i]);
        out.drift = std::max(out.drift, moved / base);
    }
    return out;
}

} // namespace pb::respond
