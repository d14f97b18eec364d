#pragma once
// After a session's timing: per variant the accuracy against the session's reference variant on
// the same frame - LDR-FLIP (mean, max), PSNR and SSIM of the tonemapped output, relative MSE
// of the linear GI irradiance (rendered with IrradianceScene: radiance * pi = the indirect
// irradiance the lighting applied) - plus the view's GI coverage under the variant's
// gi.volume_lod and its probe memory on the GPU.
#include "bench/report/BenchResult.h"
#include "frame/FrameRenderer.h"
#include "image/Image.h"
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <vector>

namespace pb::bench {

struct AccuracyInputs {
    const scene::Scene* scene = nullptr;
    const probes::ProbeSet* probes = nullptr;
    scene::View view;
    render::FrameSettings settings;
    int width = 0, height = 0;
    // Frames the irradiance renderer runs before reading; the timed renderers are read on the
    // first frame after a cut, so 1 puts a temporal history in the same state in both.
    int frames = 1;
    double pixelsPerDegree = 67.0;
};

// What the report shows of a session's accuracy: the profile variant's per-pixel FLIP map
// against the reference and the two frames it compares (tonemapped LDR, as FLIP reads them).
// Empty when not measured.
struct AccuracyPictures {
    image::ImageF flip;
    image::Image8 frame, reference;
};

// renderers[i]: the timed renderer of variant i, its last frame still in its targets (null
// when the variant did not run). `pictures` (optional) receives the profile variant's.
void captureAccuracy(SessionResult& s, const std::vector<render::FrameRenderer*>& renderers,
                     const AccuracyInputs& in, AccuracyPictures* pictures);

} // namespace pb::bench
