#include "passes/GiPassStats.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pb::render {

std::int64_t GiPassStats::totalEvaluations() const {
    std::int64_t n = 0;
    for (const GiVolumeStats& v : volumes)
        n += std::max<std::int64_t>(v.evaluatedPixels, 0);
    return n;
}

std::int64_t GiVolumeStats::wastedInvocations() const {
    if (applyInvocations < 0) return -1;
    return applyInvocations - std::max<std::int64_t>(evaluatedPixels, 0);
}

std::int64_t GiPassStats::totalApplyInvocations() const {
    std::int64_t n = 0;
    for (const GiVolumeStats& v : volumes)
        n += std::max<std::int64_t>(v.applyInvocations, 0);
    return n;
}

std::int64_t GiPassStats::totalMarkInvocations() const {
    std::int64_t n = 0;
    for (const GiVolumeStats& v : volumes)
        n += std::max<std::int64_t>(v.markInvocations, 0);
    return n;
}

bool GiPassStats::invocationsDisagree() const {
    if (!invocationsCounted) return false;
    return std::any_of(volumes.begin(), volumes.end(),
                       [](const GiVolumeStats& v) { return v.wastedInvocations() > 0; });
}

std::int64_t GiPassStats::coveredPixels() const {
    return std::count_if(evaluations.begin(), evaluations.end(),
                         [](std::uint8_t e) { return e > 0; });
}

std::string giVolumeDrawing(const GiVolumeStats& v) {
    if (v.culled) return "culled";
    if (!v.cameraInside && v.fullScreen) return "full-screen"; // naive
    const std::string drawn = v.fullScreen     ? "full-screen (inside)"
                              : v.cameraInside ? "back faces (inside)"
                                               : "box";
    if (!v.fillPass) return drawn;
    if (v.markInApply) return drawn + ", apply marks";
    return drawn + (v.rasterInfluence ? " + raster mark" : " + mark");
}

nlohmann::json giPassStatsJson(const GiPassStats& s) {
    nlohmann::json volumes = nlohmann::json::array();
    for (const GiVolumeStats& v : s.volumes) {
        nlohmann::json evaluated = nullptr; // not counted
        if (s.counted) evaluated = v.culled ? 0 : v.evaluatedPixels;
        nlohmann::json apply = nullptr, mark = nullptr, wasted = nullptr;
        if (s.invocationsCounted) {
            apply = std::max<std::int64_t>(v.applyInvocations, 0);
            mark = std::max<std::int64_t>(v.markInvocations, 0);
            wasted = std::max<std::int64_t>(v.wastedInvocations(), 0);
        }
        volumes.push_back({{"name", v.name},
                           {"file_index", v.fileIndex},
                           {"drawn", giVolumeDrawing(v)},
                           {"culled", v.culled},
                           {"camera_inside", v.cameraInside},
                           {"fill_pass", v.fillPass},
                           {"full_screen", v.fullScreen},
                           {"raster_influence", v.rasterInfluence},
                           {"mark_in_apply", v.markInApply},
                           {"evaluated_pixels", evaluated},
                           {"apply_invocations", apply},
                           {"mark_invocations", mark},
                           {"wasted_invocations", wasted}});
    }
    nlohmann::json j{{"multi_volume", s.multiVolume},
                     {"target", {{"width", s.width}, {"height", s.height}}},
                     {"volumes", volumes},
                     {"counted", s.counted}};
    if (s.counted) {
        j["evaluations"] = s.totalEvaluations();
        j["covered_pixels"] = s.coveredPixels();
    }
    j["invocations_counted"] = s.invocationsCounted;
    j["invocations_note"] = s.invocationsNote;
    j["invocations_early_tests"] = s.invocationsEarlyTests;
    j["invocations_agree"] =
        s.invocationsCounted ? nlohmann::json(!s.invocationsDisagree()) : nlohmann::json(nullptr);
    return j;
}

std::string giPassStatsText(const GiPassStats& s) {
    std::ostringstream out;
    out << "gi pass: gi.multi_volume=" << s.multiVolume << ", target " << s.width << "x" << s.height
        << ", volumes in draw order:\n";
    char line[240];
    for (const GiVolumeStats& v : s.volumes) {
        std::string invocations;
        if (s.invocationsCounted && !v.culled)
            invocations = ", invocations: apply " + std::to_string(v.applyInvocations) + ", mark " +
                          std::to_string(v.markInvocations);
        std::snprintf(
            line, sizeof line, "  %-24s %-22s %s%s\n", v.name.c_str(), giVolumeDrawing(v).c_str(),
            !s.counted ? "(not counted)"
            : v.culled ? "0 pixels"
                       : (std::to_string(v.evaluatedPixels) + " pixels evaluated").c_str(),
            invocations.c_str());
        out << line;
    }
    if (s.counted) {
        const std::int64_t covered = s.coveredPixels(), evals = s.totalEvaluations();
        std::snprintf(line, sizeof line,
                      "  total: %lld evaluations for %lld covered pixels (%.2f per pixel)\n",
                      static_cast<long long>(evals), static_cast<long long>(covered),
                      covered > 0 ? double(evals) / double(covered) : 0.0);
        out << line;
        if (!s.invocationsCounted) {
            out << "  invocations: " << s.invocationsNote << "\n";
        } else {
            std::snprintf(line, sizeof line, "  invocations: apply %lld, mark %lld (%s)\n",
                          static_cast<long long>(s.totalApplyInvocations()),
                          static_cast<long long>(s.totalMarkInvocations()),
                          s.invocationsEarlyTests ? "apply tests kept early"
                                                  : "counter forced late tests");
            out << line;
            std::int64_t wasted = 0;
            for (const GiVolumeStats& v : s.volumes)
                wasted += std::max<std::int64_t>(v.wastedInvocations(), 0);
            if (s.invocationsDisagree())
                out << "  DISAGREE: " << wasted
                    << " apply invocations evaluated nothing (discarded: sky, outside the "
                       "influence, dynamic pixels)\n";
            else
                out << "  invocations agree with evaluated pixels\n";
        }
    }
    return out.str();
}

} // namespace pb::render
