#pragma once
// Does a probe lookup print its lattice on flat surfaces? (issue 24) Irradiance looked up along
// straight lines on floors, compared with a direct gather at the same points (SurfaceGather.h):
// whatever the probes get wrong that repeats with the probe spacing - bright rings under the
// probes, dark lines at cell boundaries - shows as power at the spacing's frequency in the
// residual, far above its neighbouring frequencies. Two figures per line:
//   relative RMS error   sqrt(mean((E_probe - E_truth)^2)) / mean(E_truth)  (luminance);
//   lattice score        the residual's power at the spacing's frequency over the mean power
//                        at the frequencies 2 and 3 bins either side (detrended, Hann window).
// A lookup without a lattice pattern scores about 1 (noise and slow trends spread evenly);
// the uniform grid over Sponza's floor scored 5-28 when the issue was filed.
#include "raytrace/RayScene.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace pb::studies {

// A line of `samples` points `step` apart from `start` along `axis` (a unit world axis) on one
// flat, upward-facing surface, each point lifted off it by a hair.
struct FloorLine {
    glm::vec3 start, axis;
    float step = 0.0f;
    int samples = 0;
    glm::vec3 point(int i) const { return start + axis * (step * float(i)); }
};

// Up to `count` lines of `samples` points `step` apart along world X or Z (tried in turn) on
// upward-facing surfaces (normal within ~2.5 degrees of +Y; a double-sided face counts with
// either winding) that stay flat (every point's surface at the first point's height, within
// step / 8) and open above over their whole length (nothing within 4 steps, and the first
// thing above is a ceiling seen from below or double-sided, not the inside of a solid, and no
// point inside geometry by MidAirSamples.h's test). Starts are random in the scene's bounds,
// dropped to the first surface below (seeded: the same lines for the same scene); 4000 * count
// tries at most.
// Starts above `startBelow` are not drawn: a height a little over a storey's floor keeps the
// lines on that storey (the roofs of a tall scene would otherwise take most of them).
std::vector<FloorLine> findFloorLines(const raytrace::RayScene& rs, int count, int samples,
                                      float step, std::uint64_t seed = 0x11A77ECEu,
                                      float startBelow = std::numeric_limits<float>::infinity());

// The residual's power at `frequency` (cycles per unit length) over the mean power 2 and 3
// bins either side (a bin: 1 / (samples x step)), after removing its mean and linear trend and
// applying a Hann window. 0 when the neighbours hold no power at all (a flat residual).
double latticeScore(const std::vector<double>& residual, float step, float frequency);

} // namespace pb::studies
