#pragma once
// What the GI apply pass did in its last frame, per volume, for reports and the benchmark
// (GiApplyPass::stats()). Pixel counts exist only while counting is on
// (GiApplyPass::setCountPixels): counting reads the GPU back after every volume, so it is a
// diagnostic mode, never part of a timed frame.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pb::render {

struct GiVolumeStats {
    std::string name;
    int fileIndex = 0;   // in the probe set
    bool culled = false; // outside the view frustum: nothing drawn
    // ... of which: the corner test kept it, but no part of its box lies in the frustum
    // (GiVolumeRaster::screenRect is empty).
    bool offScreen = false;
    // GI target texels the volume's draws were scissored to (x0, y0, x1, y1: x1, y1 exclusive;
    // GiVolumeRaster::screenRect); the whole target when not scissored.
    int screenRect[4] = {0, 0, 0, 0};
    bool cameraInside = false; // stencil: drawn with the box's back faces or full-screen
    bool fillPass = false;     // stencil: the volume marks its pixels (all but the last)
    // Drawn as a full-screen triangle (naive; stencil when the camera is inside a box that
    // reaches past the far plane) rather than as the volume's box.
    bool fullScreen = false;
    // Stencil, eye inside the box: the back faces' depth test decides the influence (the apply
    // skips its influence test, the mark has an empty shader and early tests).
    bool rasterInfluence = false;
    // ... and the apply sets 'taken' itself (no discard in it): no separate mark draw.
    bool markInApply = false;
    // GI target pixels this volume's full lookup evaluated (wrote), -1 when not counted.
    std::int64_t evaluatedPixels = -1;
    // Fragment-shader invocations the device ran (an atomic counter, GLES 3.1), -1 when not
    // counted: of the apply draw, and of the mark draw (stencil, 0 without a mark).
    std::int64_t applyInvocations = -1;
    std::int64_t markInvocations = -1;
    // Apply invocations that evaluated nothing (sky, outside the influence, dynamic pixels):
    // discarded after the shader ran. 0 when the two counts agree; -1 when not counted.
    std::int64_t wastedInvocations() const;
};

struct GiPassStats {
    std::string multiVolume;            // gi.multi_volume of the frame
    int width = 0, height = 0;          // the GI target's texels
    std::vector<GiVolumeStats> volumes; // in the order drawn (culled ones included)
    bool counted = false;
    // Invocations: counted (GL_MAX_FRAGMENT_ATOMIC_COUNTERS > 0 on an ES 3.1 context), else why
    // not ("not counted: ...").
    bool invocationsCounted = false;
    std::string invocationsNote;
    // Whether the counter variant kept the apply's tests early (GI_COUNT_EARLY_TESTS).
    bool invocationsEarlyTests = true;
    // Counting only, per GI texel in GL order (row 0 at the bottom), width x height:
    std::vector<std::uint8_t> evaluations; // full lookups of the texel (saturates at 255)
    std::vector<std::int16_t> shadedBy;    // index into `volumes` of the final value, -1 none
    std::int64_t totalEvaluations() const;
    std::int64_t coveredPixels() const; // texels evaluated at least once
    std::int64_t totalApplyInvocations() const;
    std::int64_t totalMarkInvocations() const;
    // Invocations counted and, for some volume, apply invocations != evaluated pixels.
    bool invocationsDisagree() const;
};

// How a volume was drawn, in words: "culled", "full-screen" (naive); stencil: "box", "back
// faces (inside)" or "full-screen (inside)", with " + mark" for all but the last volume.
std::string giVolumeDrawing(const GiVolumeStats& v);
// The stats without the per-texel maps: multi_volume, target size, per volume name,
// file_index, drawn, culled, camera_inside, fill_pass, full_screen, evaluated_pixels (null when
// not counted), apply_invocations, mark_invocations, wasted_invocations (null when not
// counted), and when counted evaluations and covered_pixels; invocations_counted,
// invocations_note, invocations_early_tests, invocations_agree (null when not counted).
nlohmann::json giPassStatsJson(const GiPassStats& s);
// An aligned table for people (one line per volume and a total line).
std::string giPassStatsText(const GiPassStats& s);

} // namespace pb::render
