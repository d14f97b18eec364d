#include "costmodel/PixelOrder.h"

#include "core/Error.h"

namespace pb::costmodel {

std::vector<glm::ivec2> gpuPixelOrder(int width, int height, int tile) {
    if (width < 1 || height < 1) throw Error("pixel order: target must be at least 1x1");
    if (tile < 2 || tile % 2 != 0) throw Error("pixel order: tile size must be even and >= 2");
    std::vector<glm::ivec2> out;
    out.reserve(size_t(width) * size_t(height));
    for (int ty = 0; ty < height; ty += tile)
        for (int tx = 0; tx < width; tx += tile)
            for (int qy = ty; qy < std::min(ty + tile, height); qy += 2)
                for (int qx = tx; qx < std::min(tx + tile, width); qx += 2)
                    for (int p = 0; p < 4; ++p) {
                        const int x = qx + (p & 1), y = qy + (p >> 1);
                        if (x < width && y < height) out.push_back({x, y});
                    }
    return out;
}

} // namespace pb::costmodel
