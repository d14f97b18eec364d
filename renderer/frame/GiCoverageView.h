#pragma once
// Debug view volume_coverage, made on the CPU from the apply pass's per-texel counts
// (GiPassStats, counting on): an image twice the frame's width. Left: the volume that shaded
// each pixel (a colour per volume, giCoverageColour); right: the full DDGI evaluations each
// pixel cost, as a heat map (1 blue, 2 green, 3 yellow, 4 or more red) - naive shows the
// overdraw of nested volumes, stencil a single evaluation. Pixels no volume shaded show the
// frame in dim grey. GI texels are drawn over the GBuffer pixels they stand for.
#include "image/Image.h"
#include "passes/GiPassStats.h"

#include <array>
#include <string>

namespace pb::render {

// By the volume's index in the probe file, so naive and stencil frames use the same colours.
std::array<std::uint8_t, 3> giCoverageColour(int fileIndex);
std::array<std::uint8_t, 3> giEvaluationsColour(int evaluations); // the heat ramp
std::string giCoverageLegend(const GiPassStats& stats);           // one line per volume

// frame: the tonemapped frame (for context). Throws pb::Error without counts.
image::Image8 giCoverageImage(const GiPassStats& stats, const image::Image8& frame);

} // namespace pb::render
