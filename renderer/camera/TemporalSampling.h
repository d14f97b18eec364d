#pragma once
// The per-frame decisions of gi.upsample=temporal that need no GL: where the low-resolution
// GI pass samples inside each texel's footprint this frame (the jitter), and when the camera
// moved so much that the history must be dropped (a cut).
#include "camera/Reprojection.h"

#include <cstdint>
#include <glm/glm.hpp>

namespace pb::camera {

// Frames after which every GBuffer pixel of a divisor x divisor footprint was sampled once.
int jitterPeriod(int divisor);

// The GBuffer pixel, inside each low-resolution texel's divisor x divisor footprint, that the
// GI apply pass evaluates on frame `index` after a history reset. Index 0 (and the
// non-temporal modes, which always use 0) is (divisor - 1) / 2 on each axis - the pixel nearest
// the footprint's centre, what the apply pass sampled before jitter existed. The sequence
// visits every pixel of the footprint once per period in ordered-dither (Bayer) order, so
// consecutive frames land far apart and a partly converged history has no directional bias.
// divisor must be a power of two <= 16.
glm::ivec2 giJitter(int divisor, std::uint64_t index);

// When the camera jumped rather than moved: the history cannot be reprojected usefully. The
// renderer also offers an explicit reset (FrameRenderer::resetGiHistory) for cuts an
// application knows about; this rule catches the ones it does not announce.
struct CameraCutRule {
    double maxTurnDegrees = 45.0; // view direction change in one frame
    double maxMoveFraction = 0.1; // eye travel in one frame / the far plane (the scene's
                                  // extent seen from the eye, passes/RenderView.cpp)
    double maxFovChangeDegrees = 0.5;
};

// True when `cur` cannot reuse `prev`'s history: another viewport size, a zoom, a turn or a
// move beyond the rule's limits.
bool isCameraCut(const CameraState& prev, const CameraState& cur, const CameraCutRule& rule = {});

} // namespace pb::camera
