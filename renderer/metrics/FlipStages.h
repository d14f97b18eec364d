#pragma once
// The two pipelines of LDR-FLIP (see Flip.cpp for the paper's equations), exposed so tests can
// check each against a direct evaluation of the paper's definitions.
#include "image/Image.h"
#include "metrics/SeparableFilter.h"

#include <array>

namespace pb::metrics::flip {

// The image in YCxCz after the contrast-sensitivity filters (colour pipeline steps 1-2).
std::array<Plane, 3> csfFilteredOpponent(const image::Image8& img, double ppd);
// Per-pixel colour error in [0,1] after HyAB and the redistribution (steps 1-6).
Plane colourError(const image::Image8& test, const image::Image8& reference, double ppd);

// Y/Yn of the linear RGB of an 8-bit sRGB image (step 7).
Plane luminance(const image::Image8& img);
// Edge and point detector magnitudes of a luminance plane (step 8).
struct FeatureResponse {
    Plane edges, points;
};
FeatureResponse featureResponse(const Plane& luminance, double ppd);
// (max(|dEdge|, |dPoint|) / sqrt 2)^qf per pixel, in [0,1] (step 8).
Plane featureError(const image::Image8& test, const image::Image8& reference, double ppd);

} // namespace pb::metrics::flip
