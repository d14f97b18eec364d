// composite_tonemap.frag and common_color.glsl's linearToSrgb on the CPU, so the truth's PNG is
// encoded exactly as the renderer's.
#include "truth/PathTracer.h"

#include "truth/Srgb.h"

#include <algorithm>
#include <cmath>

namespace pb::truth {
namespace {

float acesFit(float x) {
    return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

} // namespace

image::Image8 tonemap(const image::ImageF& hdr, float exposure) {
    image::Image8 out;
    out.width = hdr.width;
    out.height = hdr.height;
    out.pixels.assign(size_t(hdr.width) * size_t(hdr.height) * 4, 255);
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) {
            float c[3];
            bool bad = false;
            for (int k = 0; k < 3; ++k) {
                c[k] = (k < hdr.channels ? hdr.at(x, y, k) : 0.0f) * exposure;
                bad = bad || !std::isfinite(c[k]);
            }
            for (int k = 0; k < 3; ++k) {
                float v = bad ? 0.0f : linearToSrgb(acesFit(std::max(c[k], 0.0f)));
                out.pixels[(size_t(y) * size_t(hdr.width) + size_t(x)) * 4 + size_t(k)] =
                    std::uint8_t(std::lround(v * 255.0f));
            }
        }
    return out;
}

} // namespace pb::truth
