// Relative MSE of linear HDR data (e.g. GI irradiance), scale-free so that dim and bright
// scenes are comparable.
#include "metrics/ImageChecks.h"
#include "metrics/ImageMetrics.h"

#include <algorithm>
#include <limits>

namespace pb::metrics {

double relativeMse(const image::ImageF& test, const image::ImageF& reference) {
    requireComparable("relativeMse", test, reference);
    const int colourChannels = std::min(test.channels, 3); // alpha / weight is not radiance
    double errorSum = 0, referenceSum = 0;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x)
            for (int c = 0; c < colourChannels; ++c) {
                const double r = reference.at(x, y, c);
                const double d = double(test.at(x, y, c)) - r;
                errorSum += d * d;
                referenceSum += r * r;
            }
    // 0/0: a black reference matched exactly is no error; any error against black is
    // unbounded relative to it.
    if (referenceSum == 0) return errorSum == 0 ? 0.0 : std::numeric_limits<double>::infinity();
    return errorSum / referenceSum;
}

} // namespace pb::metrics
