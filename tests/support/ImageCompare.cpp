#include "support/ImageCompare.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace pb::test {

std::string ImageDiff::describe() const {
    std::ostringstream s;
    if (!sameSize) return "image sizes differ";
    s << "max channel diff " << maxDiff << ", mean " << meanDiff << ", " << fractionOver * 100
      << "% of pixels over tolerance";
    return s.str();
}

ImageDiff compareImages(const image::Image8& a, const image::Image8& b, const ImageTolerance& tol) {
    ImageDiff d;
    d.sameSize = a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size();
    if (!d.sameSize) return d;
    size_t pixels = size_t(a.width) * a.height, over = 0;
    double sum = 0;
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            int diff = std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]));
            worst = std::max(worst, diff);
            sum += diff;
        }
        d.maxDiff = std::max(d.maxDiff, worst);
        if (worst > tol.maxChannelDiff) ++over;
    }
    d.meanDiff = pixels ? sum / double(pixels * 3) : 0.0;
    d.fractionOver = pixels ? double(over) / double(pixels) : 0.0;
    return d;
}

bool withinTolerance(const ImageDiff& d, const ImageTolerance& tol) {
    return d.sameSize && d.fractionOver <= tol.allowedOverFraction && d.meanDiff <= tol.maxMeanDiff;
}

void writeFailureImages(const std::filesystem::path& dir, const image::Image8& a,
                        const image::Image8& b) {
    std::filesystem::create_directories(dir);
    image::writePng((dir / "actual.png").string(), a);
    if (a.width != b.width || a.height != b.height) return;
    image::Image8 diff = a;
    for (size_t i = 0; i < diff.pixels.size(); ++i)
        diff.pixels[i] = (i % 4 == 3) ? 255
                                      : uint8_t(std::min(255, 16 * std::abs(int(a.pixels[i]) -
                                                                            int(b.pixels[i]))));
    image::writePng((dir / "diff.png").string(), diff);
    image::writePng((dir / "expected.png").string(), b);
}

} // namespace pb::test
