// PSNR over the three colour channels of 8-bit images.
#include "metrics/ImageChecks.h"
#include "metrics/ImageMetrics.h"

#include <cmath>
#include <limits>

namespace pb::metrics {

double psnr(const image::Image8& test, const image::Image8& reference) {
    requireComparable("psnr", test, reference);
    // Integer sum of squared differences: exact, so identical images give exactly 0.
    unsigned long long sse = 0;
    for (size_t i = 0; i < test.pixels.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            const long long d =
                static_cast<long long>(test.pixels[i + c]) - reference.pixels[i + c];
            sse += static_cast<unsigned long long>(d * d);
        }
    if (sse == 0) return std::numeric_limits<double>::infinity();
    const double mse = double(sse) / (double(test.width) * test.height * 3.0);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

} // namespace pb::metrics
