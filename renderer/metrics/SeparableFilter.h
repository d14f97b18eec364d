#pragma once
// Separable convolution of one image plane with clamp-to-edge borders (FLIP's choice: the
// border pixel is repeated). A 2D kernel k(x) * k'(y) applied as two 1D passes gives exactly
// the 2D result, also at the borders, because clamping acts on x and y independently.
#include <cstddef>
#include <vector>

namespace pb::metrics {

using std::size_t;

struct Plane {
    int width = 0, height = 0;
    std::vector<double> v; // row-major, top row first
    double& at(int x, int y) { return v[size_t(y) * width + x]; }
    double at(int x, int y) const { return v[size_t(y) * width + x]; }
};

// `horizontal` and `vertical` have odd lengths; their centre tap is offset 0.
Plane convolveSeparable(const Plane& in, const std::vector<double>& horizontal,
                        const std::vector<double>& vertical);

} // namespace pb::metrics
