#pragma once
// What the stress sweep measures on a frame: non-finite pixels and the relative error of the
// linear radiance against the reference frame. GL-free.
//
// Relative error of a pixel: the largest over R, G, B of |t - r| / max(|r|, 1e-3 * R), R the
// reference's largest finite value (so black pixels of a bright frame do not explode the
// ratio). Non-finite pixels (any channel NaN or +-Inf) are counted, not averaged; a pixel the
// reference has non-finite is skipped (the reference is built to have none).
#include "image/Image.h"

#include <cstdint>
#include <string>

namespace pb::stress {

struct Measurement {
    std::int64_t pixels = 0;
    std::int64_t nonfinitePixels = 0;   // in the final radiance
    std::int64_t nonfiniteGiTexels = 0; // in the GI evaluation target (diagnostic)
    double maxRel = 0, meanRel = 0, medianRel = 0;
    std::string error; // the render failed (a GL error, an unsupported format): why
};

// Throws pb::Error when the sizes differ.
Measurement compareRadiance(const image::ImageF& test, const image::ImageF& reference);

std::int64_t countNonfinitePixels(const image::ImageF& img); // first 3 channels

struct BreakThresholds {
    double medianRel = 0.05; // "wrong": half the pixels off by more than this
};

// "error", "nan/inf", "wrong" or "ok".
std::string symptom(const Measurement& m, const BreakThresholds& t);
inline bool broken(const Measurement& m, const BreakThresholds& t) {
    return symptom(m, t) != "ok";
}

} // namespace pb::stress
