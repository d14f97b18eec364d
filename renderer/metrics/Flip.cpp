// LDR-FLIP, implemented from the paper: P. Andersson, J. Nilsson, T. Akenine-Moller,
// M. Oskarsson, K. Astrom, M. D. Fairchild, "FLIP: A Difference Evaluator for Alternating
// Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2) (HPG 2020).
//
// What is implemented (the paper's LDR pipeline, in its order):
//  Colour pipeline
//   1. 8-bit sRGB -> linear RGB -> XYZ (D65) -> YCxCz opponent space.
//   2. Spatial (CSF) filtering per opponent channel. Each channel's contrast sensitivity is a
//      sum of two Gaussians in frequency, S(f) = a1 exp(-b1 f^2) + a2 exp(-b2 f^2), whose
//      spatial counterpart is s(x) = a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + (same for a2, b2),
//      x in degrees (pixel offset / pixels per degree), evaluated at the 2D distance and
//      normalized to sum 1. Constants (achromatic, red-green, blue-yellow):
//        a1 = 1, 1, 34.1   b1 = 0.0047, 0.0053, 0.04   a2 = 0, 0, 13.5   b2 = 1e-5, 1e-5, 0.025
//      Kernel radius ceil(3 sqrt(b_max / (2 pi^2)) ppd) with b_max = 0.04.
//   3. Back to linear RGB, clamped to [0,1] (the gamut of the display), -> CIELAB.
//   4. Hunt adjustment: a* and b* scaled by 0.01 L*.
//   5. HyAB distance |dL| + sqrt(da^2 + db^2).
//   6. Redistribution: e = HyAB^qc, qc = 0.7; cmax = (HyAB of Hunt-adjusted pure green and pure
//      blue)^qc; errors below pc cmax (pc = 0.4) map linearly to [0, pt] (pt = 0.95), the rest
//      linearly from pt to 1 at cmax.
//  Feature pipeline
//   7. Luminance Y/Yn of the unfiltered linear RGB, in [0,1].
//   8. Edges: first derivative of a Gaussian; points: second derivative of a Gaussian;
//      sigma = 0.5 w ppd with w = 0.082 degrees, radius ceil(3 sigma). Each kernel's positive
//      weights are scaled to sum to 1 and its negative weights to -1. Magnitudes of the x/y
//      responses are compared: df = (max(|dEdge|, |dPoint|) / sqrt(2))^qf, qf = 0.5.
//  Combination
//   9. FLIP = colourError^(1 - featureError) per pixel; mean and max over the image.
//
// Simplifications / implementation choices (none changes the result beyond rounding):
//  - all kernels are applied as separable 1D passes; the sum-of-two-Gaussians CSF is applied as
//    two separable Gaussians weighted by their shares of the 2D kernel's sum, which equals the
//    2D kernel on the same square support;
//  - borders repeat the edge pixel; arithmetic is in double;
//  - the per-pixel error is clamped to 1 (the redistribution exceeds 1 only for colour pairs
//    farther apart than green and blue, which the paper's cmax takes as the largest);
//  - when a detector kernel has no positive (or negative) weight left at a tiny ppd, that part
//    stays zero instead of dividing by zero.
#include "core/Error.h"
#include "metrics/FlipStages.h"
#include "metrics/ImageChecks.h"
#include "metrics/ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pb::metrics {

FlipResult ldrFlip(const image::Image8& test, const image::Image8& reference,
                   double pixelsPerDegree) {
    requireComparable("ldrFlip", test, reference);
    if (!(pixelsPerDegree > 0) || !std::isfinite(pixelsPerDegree))
        throw Error("ldrFlip: pixels per degree must be positive and finite, got " +
                    std::to_string(pixelsPerDegree));
    const Plane colour = flip::colourError(test, reference, pixelsPerDegree);
    const Plane feature = flip::featureError(test, reference, pixelsPerDegree);

    FlipResult result;
    result.map.width = test.width;
    result.map.height = test.height;
    result.map.channels = 1;
    result.map.pixels.resize(colour.v.size());
    double sum = 0;
    for (size_t i = 0; i < colour.v.size(); ++i) {
        // Step 9. The redistribution passes 1 only for colours farther apart than green and
        // blue.
        const double e = std::min(1.0, std::pow(colour.v[i], 1 - feature.v[i]));
        result.map.pixels[i] = float(e);
        sum += e;
        result.max = std::max(result.max, e);
    }
    result.mean = sum / double(colour.v.size());
    return result;
}

} // namespace pb::metrics
