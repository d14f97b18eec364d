#pragma once
// Image-error metrics for the benchmark's accuracy columns: PSNR, SSIM, LDR-FLIP on displayable
// 8-bit sRGB images, relative MSE on linear HDR data (GI irradiance), and a heat-map ramp for
// error maps. GL-free. README.md in this folder gives each metric's source and simplifications.
#include "image/Image.h"

namespace pb::metrics {

// All functions throw pb::Error when the two images differ in size (or channel count for
// ImageF) or an image is empty.

// PSNR over R, G and B (alpha ignored), peak 255: 10 log10(255^2 / MSE). +inf when identical.
double psnr(const image::Image8& test, const image::Image8& reference);

// Mean SSIM of the luma (Rec. 601 weights on the 8-bit values), Wang et al. 2004: 11x11
// Gaussian window, sigma 1.5, K1 = 0.01, K2 = 0.03, L = 255. Near the border the window is
// clipped to the image and renormalized, so every pixel (even of a 1x1 image) has a value.
double ssim(const image::Image8& test, const image::Image8& reference);

struct FlipResult {
    double mean = 0;
    double max = 0;
    image::ImageF map; // 1 channel: the per-pixel error in [0,1]
};

// LDR-FLIP (Andersson et al. 2020) of two 8-bit sRGB images viewed at `pixelsPerDegree`
// (67 = a 0.7 m wide 4K monitor seen from 0.7 m, the paper's default). Throws pb::Error for a
// non-positive or non-finite pixelsPerDegree.
FlipResult ldrFlip(const image::Image8& test, const image::Image8& reference,
                   double pixelsPerDegree = 67.0);

// Relative MSE of linear HDR data: sum over pixels and RGB of (t - r)^2 / sum of r^2.
// 0/0 (both all zero) is 0; a non-zero error against an all-zero reference is +inf.
double relativeMse(const image::ImageF& test, const image::ImageF& reference);

// Colours channel 0 of `errorMap` with a ramp whose luma rises monotonically: 0 is black,
// `maxValue` and above (and NaN) the brightest colour. Throws pb::Error for maxValue <= 0.
image::Image8 errorHeatMap(const image::ImageF& errorMap, float maxValue = 1.0f);

} // namespace pb::metrics
