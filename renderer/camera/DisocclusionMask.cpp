#include "camera/DisocclusionMask.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>

namespace pb::camera {

std::vector<PixelHistory> disocclusionMask(const CameraState& prev, const image::ImageF& prevDepth,
                                           const CameraState& cur, const image::ImageF& curDepth) {
    if (curDepth.width != cur.width || curDepth.height != cur.height ||
        prevDepth.width != prev.width || prevDepth.height != prev.height)
        throw Error("disocclusionMask: depth images do not match their cameras");
    const int w = cur.width, h = cur.height;
    std::vector<PixelHistory> mask(size_t(w) * size_t(h), PixelHistory::Seen);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (curDepth.at(x, y, 0) <= 0.0f) continue; // sky
            const int glRow = h - 1 - y;
            const PixelReprojection r =
                reprojectPixel(prev, cur, glm::vec2(x + 0.5f, glRow + 0.5f), curDepth.at(x, y, 1));
            const size_t index = size_t(y) * size_t(w) + size_t(x);
            if (!r.onScreen) {
                mask[index] = PixelHistory::EnteredScreen;
                continue;
            }
            bool seen = false;
            const glm::ivec2 base(glm::floor(r.prevWindow - 0.5f));
            for (int k = 0; k < 4 && !seen; ++k) {
                const int px = std::clamp(base.x + (k & 1), 0, prev.width - 1);
                const int pyGl = std::clamp(base.y + (k >> 1), 0, prev.height - 1);
                const float d = prevDepth.at(px, prev.height - 1 - pyGl, 0);
                seen = d > 0.0f && std::abs(d - r.prevDistance) <=
                                       kDisocclusionDistanceTolerance * r.prevDistance;
            }
            mask[index] = seen ? PixelHistory::Seen : PixelHistory::WasHidden;
        }
    return mask;
}

} // namespace pb::camera
