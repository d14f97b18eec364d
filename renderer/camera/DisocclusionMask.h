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

// `depth` images as frame/DepthReadback reads them: rows top to bottom, channel 0 the
// distance from the eye (0 = sky), channel 1 the window depth. Returns one byte per pixel
// (rows top to bottom): 1 where this frame sees a surface that was off-screen or hidden in the
// previous frame - none of the 2x2 previous pixels around its reprojected position holds a
// surface within the tolerance of its expected distance -, 0 elsewhere (and on sky).
std::vector<std::uint8_t> disocclusionMask(const CameraState& prev, const image::ImageF& prevDepth,
                                           const CameraState& cur, const image::ImageF& curDepth);

} // namespace pb::camera
