#include "stress/StressMetrics.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pb::stress {

namespace {
bool finitePixel(const float* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}
} // namespace

std::int64_t countNonfinitePixels(const image::ImageF& img) {
    std::int64_t n = 0;
    const std::size_t c = std::size_t(img.channels);
    for (std::size_t i = 0; i + c <= img.pixels.size(); i += c)
        n += finitePixel(&img.pixels[i]) ? 0 : 1;
    return n;
}

Measurement compareRadiance(const image::ImageF& test, const image::ImageF& reference) {
    if (test.width != reference.width || test.height != reference.height ||
        test.channels != reference.channels || test.channels < 3)
        throw Error("stress: frames of different sizes cannot be compared");
    const std::size_t c = std::size_t(test.channels);
    float largest = 0.0f;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i)
        if (i % c < 3 && std::isfinite(reference.pixels[i]))
            largest = std::max(largest, std::abs(reference.pixels[i]));
    const double floor = std::max(1e-3 * double(largest), 1e-30);

    Measurement m;
    m.pixels = std::int64_t(test.width) * test.height;
    std::vector<float> rel;
    rel.reserve(std::size_t(m.pixels));
    for (std::size_t i = 0; i + c <= test.pixels.size(); i += c) {
        const float* t = &test.pixels[i];
        const float* r = &reference.pixels[i];
        if (!finitePixel(t)) {
            ++m.nonfinitePixels;
            continue;
        }
        if (!finitePixel(r)) continue;
        double e = 0.0;
        for (int k = 0; k < 3; ++k)
            e = std::max(e,
                         std::abs(double(t[k]) - r[k]) / std::max(std::abs(double(r[k])), floor));
        rel.push_back(float(e));
    }
    if (rel.empty()) return m;
    double sum = 0.0;
    for (float e : rel) {
        sum += e;
        m.maxRel = std::max(m.maxRel, double(e));
    }
    m.meanRel = sum / double(rel.size());
    auto mid = rel.begin() + std::ptrdiff_t(rel.size() / 2);
    std::nth_element(rel.begin(), mid, rel.end());
    m.medianRel = *mid;
    return m;
}

std::string symptom(const Measurement& m, const BreakThresholds& t) {
    if (!m.error.empty()) return "error";
    if (m.nonfinitePixels > 0) return "nan/inf";
    if (m.medianRel > t.medianRel) return "wrong";
    return "ok";
}

} // namespace pb::stress
