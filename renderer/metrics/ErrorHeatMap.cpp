// Heat map for error images. The ramp is our own: five control colours chosen so that luma
// (Rec. 601) rises strictly from black through violet, crimson and orange to pale yellow, so a
// brighter pixel always means a larger error, also when printed in grey.
#include "core/Error.h"
#include "metrics/ImageMetrics.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pb::metrics {
namespace {

struct Stop {
    float r, g, b;
};
// Lumas: 0, 43, 89, 159, 246 (of 255).
constexpr std::array<Stop, 5> kRamp{
    {{0, 0, 0}, {60, 20, 120}, {190, 40, 80}, {245, 140, 30}, {255, 250, 200}}};

} // namespace

image::Image8 errorHeatMap(const image::ImageF& errorMap, float maxValue) {
    if (!(maxValue > 0) || !std::isfinite(maxValue))
        throw Error("errorHeatMap: the maximum value must be positive and finite");
    if (errorMap.width <= 0 || errorMap.height <= 0 || errorMap.channels <= 0 ||
        errorMap.pixels.size() != size_t(errorMap.width) * errorMap.height * errorMap.channels)
        throw Error("errorHeatMap: empty or malformed error map");
    image::Image8 out;
    out.width = errorMap.width;
    out.height = errorMap.height;
    out.pixels.resize(size_t(out.width) * out.height * 4);
    const float segments = float(kRamp.size() - 1);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const float v = errorMap.at(x, y, 0);
            // NaN is shown as the worst error: a broken pixel must not look perfect.
            const float t = std::isnan(v) ? 1.0f : std::clamp(v / maxValue, 0.0f, 1.0f);
            const float pos = t * segments;
            const int i = std::min(int(pos), int(kRamp.size()) - 2);
            const float f = pos - float(i);
            const Stop &a = kRamp[size_t(i)], &b = kRamp[size_t(i) + 1];
            std::uint8_t* p = &out.pixels[(size_t(y) * out.width + x) * 4];
            p[0] = std::uint8_t(std::lround(a.r + (b.r - a.r) * f));
            p[1] = std::uint8_t(std::lround(a.g + (b.g - a.g) * f));
            p[2] = std::uint8_t(std::lround(a.b + (b.b - a.b) * f));
            p[3] = 255;
        }
    return out;
}

} // namespace pb::metrics
