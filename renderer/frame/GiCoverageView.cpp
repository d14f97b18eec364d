#include "frame/GiCoverageView.h"

#include "core/Error.h"

#include <algorithm>
#include <sstream>

namespace pb::render {

std::array<std::uint8_t, 3> giCoverageColour(int fileIndex) {
    static constexpr std::array<std::uint8_t, 3> kPalette[] = {
        {230, 60, 60},  {60, 170, 230}, {250, 200, 40}, {150, 90, 220},
        {60, 200, 110}, {240, 130, 40}, {230, 90, 190}, {140, 140, 140},
    };
    return kPalette[size_t(fileIndex) % std::size(kPalette)];
}

std::array<std::uint8_t, 3> giEvaluationsColour(int evaluations) {
    switch (std::min(evaluations, 4)) {
    case 1:
        return {40, 90, 255};
    case 2:
        return {40, 210, 60};
    case 3:
        return {250, 220, 30};
    case 4:
        return {240, 40, 30};
    }
    return {0, 0, 0};
}

std::string giCoverageLegend(const GiPassStats& stats) {
    std::ostringstream out;
    const char* names[] = {"red", "blue", "yellow", "purple", "green", "orange", "pink", "grey"};
    for (size_t i = 0; i < stats.volumes.size(); ++i) {
        const GiVolumeStats& v = stats.volumes[i];
        out << "  " << names[size_t(v.fileIndex) % std::size(names)] << ": " << v.name;
        if (v.culled)
            out << " (culled)";
        else
            out << ", " << v.evaluatedPixels << " pixels evaluated";
        out << "\n";
    }
    return out.str();
}

image::Image8 giCoverageImage(const GiPassStats& stats, const image::Image8& frame) {
    if (!stats.counted || stats.width <= 0)
        throw Error("volume_coverage: the GI pass did not count pixels");
    image::Image8 out;
    out.width = frame.width * 2;
    out.height = frame.height;
    out.pixels.assign(size_t(out.width) * size_t(out.height) * 4, 255);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            // The texel standing for GBuffer pixel (x, y): rows of `stats` count from the bottom.
            const int tx = std::min(x * stats.width / frame.width, stats.width - 1);
            const int ty =
                std::min((frame.height - 1 - y) * stats.height / frame.height, stats.height - 1);
            const size_t texel = size_t(ty) * size_t(stats.width) + size_t(tx);
            const double luma = (0.2126 * frame.at(x, y, 0) + 0.7152 * frame.at(x, y, 1) +
                                 0.0722 * frame.at(x, y, 2));
            const auto grey = std::uint8_t(luma * 0.35);
            const int volume = stats.shadedBy[texel], evaluations = stats.evaluations[texel];
            std::array<std::uint8_t, 3> left{grey, grey, grey}, right = left;
            // The frame's shading shows through the colours (70 % colour, 30 % luma).
            auto tint = [&](std::array<std::uint8_t, 3> c) {
                for (auto& v : c)
                    v = std::uint8_t(0.7 * v + 0.3 * luma);
                return c;
            };
            if (volume >= 0) left = tint(giCoverageColour(stats.volumes[size_t(volume)].fileIndex));
            if (evaluations > 0) right = tint(giEvaluationsColour(evaluations));
            for (int c = 0; c < 3; ++c) {
                out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * 4 + size_t(c)] =
                    left[size_t(c)];
                out.pixels[(size_t(y) * size_t(out.width) + size_t(x + frame.width)) * 4 +
                           size_t(c)] = right[size_t(c)];
            }
        }
    return out;
}

} // namespace pb::render
