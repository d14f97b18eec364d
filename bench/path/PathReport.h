#pragma once
// Per-frame error of a camera-path render against full-resolution GI (`probebench render --path
// --compare-to full`) and its summary: PSNR, LDR-FLIP, MAE, frames to converge after each cut,
// and the error at disocclusions (the ghosting measure; definitions in bench/README.md).
#include "camera/DisocclusionMask.h"
#include "image/Image.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pb::bench {

struct PathFrameError {
    int frame = 0;
    double time = 0;
    bool cut = false;         // the history was reset at this frame (path cut or frame 0)
    bool historyUsed = false; // gi.upsample=temporal reprojected the previous frame
    double psnr = 0;          // dB, +inf when identical
    double flipMean = 0, flipMax = 0;
    double mae = 0;                     // mean |test - reference| over RGB, 8-bit units
    std::int64_t enteredPixels = 0;     // surfaces off the previous frame's screen
    std::int64_t disoccludedPixels = 0; // surfaces hidden behind another in the previous frame
    double disoccludedMae = 0;          // the MAE over those pixels (0 when none)
    // The GI irradiance the lighting read (linear RGB), against full resolution's: the
    // upsampling's own error, undiluted by direct light and tonemapping.
    double giRelMse = 0;            // metrics::relativeMse
    double giRelMae = 0;            // sum |test - ref| / sum |ref| over RGB
    double disoccludedGiRelMae = 0; // the same over the disoccluded pixels
};

// Every metric of one frame; `history` has one entry per pixel (empty = none computed).
PathFrameError measurePathFrame(const image::Image8& test, const image::Image8& reference,
                                const image::ImageF& testGi, const image::ImageF& referenceGi,
                                const std::vector<camera::PixelHistory>& history);

struct PathConvergence {
    int cutFrame = 0;
    int frames = -1; // -1: the segment is too short to say
};

// For each segment that starts at a cut: the frames after the cut until the GI error (giRelMae)
// stays within 10% of the segment's last frame's (or within 1e-4 of it). Meaningful where the
// segment ends still (a converged state); on a moving segment it says when the error settled.
std::vector<PathConvergence> framesToConverge(const std::vector<PathFrameError>& frames);

std::string pathErrorsCsv(const std::vector<PathFrameError>& frames);
// {"frames": [...], "summary": {...}} plus the run's description `about`.
nlohmann::json pathErrorsJson(const std::vector<PathFrameError>& frames, nlohmann::json about);
// A few readable lines for the terminal.
std::string pathSummaryText(const std::vector<PathFrameError>& frames);

} // namespace pb::bench
