#pragma once
// probebench truth: a path-traced ground truth of a scene as the rasterizer sees it (same
// camera, GBuffer materials, sun, sky and punctual lights; README.md in this folder says what
// matches and what deliberately differs). Lambertian surfaces only, as the renderer shades.
//
// Estimator per camera ray (box-filtered over the pixel): next-event estimation to the sun and
// every punctual light (delta lights: no MIS) and to one emissive triangle drawn by power from
// an alias table, combined with cosine-weighted BSDF sampling by the power heuristic; the sky
// (a constant radiance) is reached by BSDF sampling only, which for a uniform sky is already
// proportional to the integrand. Russian roulette from the 4th vertex on.
//
// Random numbers: a pixel's samples are stratified per dimension pair, in kBatches
// independently scrambled batches (ScrambledSobol.h); at the same spp the image is less noisy
// than with independent samples. Deterministic: sample s of pixel p draws from (seed, p, s),
// and each pixel is summed by one thread in sample order, so the image is bit-identical for
// any thread count.
#include "image/Image.h"
#include "scene/Scene.h"

#include <cstdint>
#include <functional>
#include <string>

namespace pb::truth {

struct TruthSettings {
    int width = 640, height = 360;
    int spp = 64;          // samples per pixel, >= 1
    int maxDepth = 32;     // surface vertices with lighting; 1 = direct light only
    std::uint64_t seed = 1;
    int threads = 0;       // 0 = all cores
};

// The estimator's own noise: the standard error of the image's mean luminance, from each
// pixel's variance (pixels are independent: SE^2 = sum_p s_p^2 / n / P^2). s_p^2 / n is the
// variance of pixel p's mean estimated from its independent batches (ScrambledSobol.h), not
// the spread of its stratified samples.
struct TruthNoise {
    double meanLuminance = 0.0;      // Rec. 709 luminance, scene units (before exposure)
    double standardError = 0.0;      // of meanLuminance; 0 when spp < 2 (no variance estimate)
    double relativeStandardError = 0.0; // standardError / meanLuminance (0 for a black image)
    // The typical pixel's noise: sqrt(mean_p s_p^2 / n) / meanLuminance. The mean's error
    // shrinks with the pixel count; this one says how grainy the image still looks.
    double pixelRelativeStandardError = 0.0;
    // What the truth's own noise adds to a relative MSE against it: sum_p s_p^2 / n over
    // sum_p L_p^2 (luminance standing in for the RGB sums). A relative MSE near this floor says
    // more about the truth's spp than about the image compared with it.
    double relativeMseNoiseFloor = 0.0;
    bool varianceKnown = false;      // spp >= 2
};

struct TruthResult {
    image::ImageF hdr;               // linear radiance, RGBA (a = 1), rows top to bottom
    TruthNoise noise;
    std::uint64_t cameraRays = 0;
    double seconds = 0.0;
    std::string note;                // e.g. the scene has no light
};

// Throws pb::Error for bad settings (spp < 1, depth outside [1, 1024], size outside
// [1, 16384]), a degenerate camera, or a view in which no pixel sees geometry.
// `progress(done, total)` is called about every 100 ms with finished rows.
TruthResult renderTruth(const scene::Scene& scene, const scene::View& view,
                        const TruthSettings& settings,
                        const std::function<void(int done, int total)>& progress = {});

// True when something lights the scene: a sun with irradiance, a punctual light with
// intensity, an emissive visible material, or a non-black sky.
bool sceneHasLight(const scene::Scene& scene);

// The composite pass on the CPU: exposure, the ACES fit (Narkowicz 2015), sRGB encoding to
// 8 bits; NaN/Inf become black as in composite_tonemap.frag.
image::Image8 tonemap(const image::ImageF& hdr, float exposure);

} // namespace pb::truth
