#pragma once
// `bench --truth`: every variant's frame against the path-traced ground truth of the same view
// and size (renderer/truth/). The frame is the one AccuracyCapture reads (right after a camera
// cut); FLIP and PSNR on the tonemapped 8-bit output - the truth tonemapped with the frame's
// exposure exactly as the composite pass does - and relative MSE on the linear radiance. The
// reference variant gets its own error too: how far the probes are from the real answer.
#include "bench/report/BenchResult.h"
#include "frame/FrameRenderer.h"
#include "image/Image.h"
#include "metrics/ImageMetrics.h"

#include <map>
#include <utility>
#include <vector>

namespace pb::bench {

// The truth per image size (width, height), as `probebench truth` computes it.
using TruthBySize = std::map<std::pair<int, int>, image::ImageF>;

// The pictures of one session for the report (empty when the variant did not run).
struct TruthMaps {
    image::Image8 truth, reference, profile;
    image::ImageF referenceFlip, profileFlip; // 1-channel FLIP against the truth
};

// One rendered frame (the renderer's last) against the truth; `flip` (optional) receives FLIP's map.
TruthAccuracy truthAccuracyOf(render::FrameRenderer& renderer, const image::ImageF& truthHdr,
                              const image::Image8& truthLdr, double pixelsPerDegree,
                              metrics::FlipResult* flip = nullptr);

void captureTruthAccuracy(SessionResult& s, const std::vector<render::FrameRenderer*>& renderers,
                          const image::ImageF& truthHdr, float exposure, double pixelsPerDegree,
                          TruthMaps* maps);

} // namespace pb::bench
