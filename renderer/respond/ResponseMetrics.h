#pragma once
// How well a schedule followed a change, from per-frame luminance images (issue 20).
// Frame 0 is the first frame after the change, rendered with the probes as they were before
// it (no update yet): its error against the converged reference is the step to close.
//   error(n)      mean over pixels of |Y_n - Y_ref|, relative to error(0)
//   t95 / t99     the first frame from which error stays <= 5% / 1% to the end (-1: never)
//   overshoot     how far the image went past the reference, along the step: the largest
//                 -sum((Y_n - Y_ref)(Y_0 - Y_ref)) / sum((Y_0 - Y_ref)^2) over frames, >= 0
//   flicker       per-pixel coefficient of variation (std / mean of Y) over the last
//                 `window` frames, averaged over pixels with a mean above zero
//   far drift     over the "far" pixels (the caller's mask: for a local change, pixels whose
//                 surface lies beyond the radius of every change point; a global change has
//                 none), the largest mean |Y_n - Y_0| / mean Y_0 over frames: how much light
//                 that should not have changed moved
#include <cstddef>
#include <vector>

namespace pb::respond {

using LumaImage = std::vector<float>;

double meanAbsError(const LumaImage& image, const LumaImage& reference);
// -1 when it never settles.
int settleFrame(const std::vector<double>& relativeError, double tolerance);
double overshoot(const std::vector<LumaImage>& frames, const LumaImage& reference);
double flicker(const std::vector<LumaImage>& frames, std::size_t window);

struct FarDrift {
    std::size_t pixels = 0; // far pixels (0: every pixel changed; drift is then 0)
    double drift = 0.0;
};
FarDrift farDrift(const std::vector<LumaImage>& frames, const std::vector<bool>& far);

} // namespace pb::respond
