// Error report for BC6H-compressed probe textures (the bake prints it per texture).
#include "probes/bc6h/Bc6h.h"
#include "probes/bc6h/Bc6hFormat.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pb::probes {

std::size_t bc6hSizeBytes(int width, int height) {
    if (width <= 0 || height <= 0 || width % 4 != 0 || height % 4 != 0)
        throw Error("BC6H: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not a positive multiple of 4");
    return static_cast<std::size_t>(width / 4) * (height / 4) * kBc6hBlockBytes;
}

Bc6hErrorStats measureBc6hError(const float* source, int strideFloats, const float* decodedRgb,
                                int width, int height, double relativeFloor) {
    if (strideFloats < 2 || strideFloats > 4)
        throw Error("BC6H error: stride " + std::to_string(strideFloats) + " is not 2, 3 or 4");
    Bc6hErrorStats stats;
    const int channels = std::min(strideFloats, 3);
    double sumAbs = 0.0, sumRel = 0.0, sumSq = 0.0;
    const std::size_t texels = static_cast<std::size_t>(width) * height;
    for (std::size_t t = 0; t < texels; ++t) {
        for (int c = 0; c < channels; ++c) {
            const double s = bc6h::clampSource(source[t * strideFloats + c]);
            const double d = decodedRgb[t * 3 + c];
            const double abs = std::fabs(d - s);
            const double rel = abs / std::max(s, relativeFloor);
            stats.maxAbs = std::max(stats.maxAbs, abs);
            stats.maxRel = std::max(stats.maxRel, rel);
            sumAbs += abs;
            sumRel += rel;
            sumSq += abs * abs;
        }
    }
    stats.channels = texels * channels;
    if (stats.channels > 0) {
        const double n = static_cast<double>(stats.channels);
        stats.meanAbs = sumAbs / n;
        stats.meanRel = sumRel / n;
        stats.rmse = std::sqrt(sumSq / n);
    }
    return stats;
}

Bc6hErrorStats bc6hRoundTripError(const float* rgb, int width, int height, int strideFloats,
                                  Bc6hQuality q, double relativeFloor) {
    const std::vector<std::uint8_t> blocks = encodeBc6hUf16(rgb, width, height, strideFloats, q);
    const std::vector<float> decoded = decodeBc6hUf16(blocks.data(), width, height);
    return measureBc6hError(rgb, strideFloats, decoded.data(), width, height, relativeFloor);
}

} // namespace pb::probes
