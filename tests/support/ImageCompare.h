#pragma once
// Image comparison for golden and parity tests. On failure the actual image and an amplified
// difference image are written next to each other under build/test-output/<test>/.
#include "image/Image.h"

#include <filesystem>
#include <string>

namespace pb::test {

struct ImageTolerance {
    int maxChannelDiff = 0;          // no channel may differ by more (0..255)...
    double allowedOverFraction = 0;  // ...except this fraction of pixels
    double maxMeanDiff = 0;          // mean absolute channel difference (0..255)
};

// The golden-image tolerance: llvmpipe is deterministic for one build, but LLVM's code
// generation differs between CPUs (AVX2 vs AVX-512) and Mesa versions; a few LSBs on edges
// are allowed.
inline constexpr ImageTolerance kGoldenTolerance{3, 0.002, 0.25};

struct ImageDiff {
    bool sameSize = false;
    int maxDiff = 0;
    double meanDiff = 0;
    double fractionOver = 0; // pixels with a channel diff > tolerance.maxChannelDiff
    std::string describe() const;
};

ImageDiff compareImages(const image::Image8& actual, const image::Image8& expected,
                        const ImageTolerance& tol);
bool withinTolerance(const ImageDiff& d, const ImageTolerance& tol);
// Writes actual.png and diff.png (|a-b| x 16) into `dir`.
void writeFailureImages(const std::filesystem::path& dir, const image::Image8& actual,
                        const image::Image8& expected);

} // namespace pb::test
