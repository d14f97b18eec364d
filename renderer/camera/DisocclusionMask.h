#pragma once
// Which pixels of a frame show surfaces the previous frame did not (a disocclusion), from the
// two cameras and the two frames' GBuffer depths - the ground truth the ghosting measure of
// `render --path --compare-to full` is taken over (bench/README.md). Independent of the
// temporal shader's own rejection test, though built on the same reprojection.
#include "camera/Reprojection.h"
#include "image/Image.h"

#include <cstdint>
#include <vector>

namespace pb::camera {

// Relative distance mismatch above which a previous pixel shows another surface.
inline constexpr float kDisocclusionDistanceTolerance = 0.05f;

// Per pixel: seen in the previous frame, off its screen (entering at a border: no history can
// exist, no ghost can form), or on its screen but hidden behind another surface (a true
// disocclusion: where stale history would show as a ghost).
enum class PixelHistory : std::uint8_t { Seen = 0, EnteredScreen = 1, WasHidden = 2 };

// `depth` images as frame/DepthReadback reads them: rows top to bottom, channel 0 the
// distance from the eye (0 = sky), channel 1 the window depth. Returns one PixelHistory per
// pixel (rows top to bottom): EnteredScreen where the surface reprojects outside the previous
// viewport (or behind its eye), WasHidden where none of the 2x2 previous pixels around its
// reprojected position holds a surface within the tolerance of its expected distance, Seen
// elsewhere (and on sky).
std::vector<PixelHistory> disocclusionMask(const CameraState& prev, const image::ImageF& prevDepth,
                                           const CameraState& cur, const image::ImageF& curDepth);

} // namespace pb::camera
