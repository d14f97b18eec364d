#pragma once
// The order a GPU shades a full-screen pass's pixels, as the cost model assumes it: the
// target cut into square tiles (row-major, from window row 0 = the bottom, as GL counts),
// inside a tile 2x2 quads row-major, inside a quad (0,0) (1,0) (0,1) (1,1). Real GPUs run
// many tiles at once on several cores with separate L1s; the model replays one core's view:
// consecutive tiles through one cache (README: what the model does not capture).
#include <glm/glm.hpp>

#include <vector>

namespace pb::costmodel {

// Every pixel of a width x height target once, in GL window coordinates (y up). tile >= 2,
// even.
std::vector<glm::ivec2> gpuPixelOrder(int width, int height, int tile = 8);

} // namespace pb::costmodel
