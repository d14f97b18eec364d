#include "metrics/SeparableFilter.h"

#include <algorithm>

namespace pb::metrics {
namespace {

Plane pass(const Plane& in, const std::vector<double>& k, bool horizontal) {
    Plane out{in.width, in.height, std::vector<double>(in.v.size())};
    const int r = int(k.size()) / 2;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            double sum = 0;
            for (int i = -r; i <= r; ++i) {
                const int sx = horizontal ? std::clamp(x + i, 0, in.width - 1) : x;
                const int sy = horizontal ? y : std::clamp(y + i, 0, in.height - 1);
                sum += k[size_t(i + r)] * in.at(sx, sy);
            }
            out.at(x, y) = sum;
        }
    return out;
}

} // namespace

Plane convolveSeparable(const Plane& in, const std::vector<double>& horizontal,
                        const std::vector<double>& vertical) {
    return pass(pass(in, horizontal, true), vertical, false);
}

} // namespace pb::metrics
