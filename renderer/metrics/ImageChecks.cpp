#include "metrics/ImageChecks.h"

#include "core/Error.h"

#include <string>

namespace pb::metrics {
namespace {

std::string size(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

void check(const char* metric, int tw, int th, size_t tPixels, int rw, int rh, size_t rPixels,
           size_t perPixelT, size_t perPixelR) {
    if (tw <= 0 || th <= 0 || rw <= 0 || rh <= 0)
        throw Error(std::string(metric) + ": empty image (test " + size(tw, th) + ", reference " +
                    size(rw, rh) + ")");
    if (tw != rw || th != rh)
        throw Error(std::string(metric) + ": sizes differ: test " + size(tw, th) + ", reference " +
                    size(rw, rh));
    // A malformed image (pixel vector shorter than its size) would otherwise read out of bounds.
    if (tPixels != size_t(tw) * th * perPixelT || rPixels != size_t(rw) * rh * perPixelR)
        throw Error(std::string(metric) + ": pixel data does not match the image size");
}

} // namespace

void requireComparable(const char* metric, const image::Image8& test,
                       const image::Image8& reference) {
    check(metric, test.width, test.height, test.pixels.size(), reference.width, reference.height,
          reference.pixels.size(), 4, 4);
}

void requireComparable(const char* metric, const image::ImageF& test,
                       const image::ImageF& reference) {
    if (test.channels != reference.channels || test.channels <= 0)
        throw Error(std::string(metric) + ": channel counts differ: test " +
                    std::to_string(test.channels) + ", reference " +
                    std::to_string(reference.channels));
    check(metric, test.width, test.height, test.pixels.size(), reference.width, reference.height,
          reference.pixels.size(), size_t(test.channels), size_t(reference.channels));
}

} // namespace pb::metrics
