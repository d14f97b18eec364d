#include "frame/FrameSkips.h"

#include "profile/GiVolumeLod.h"
#include "passes/DynamicObjects.h"

#include <algorithm>
#include <cstdio>

namespace pb::render {

std::string shadowSkipReason(const scene::Scene& s) {
    const char* unshadowed = s.lights.empty() ? "" : "; punctual lights cast no shadows";
    if (!s.sun.enabled) return std::string("the sun is off") + unshadowed;
    if (s.sun.intensity * s.sun.color == glm::vec3(0.0f))
        return std::string("the sun has zero irradiance") + unshadowed;
    if (s.worldBounds().empty()) return "the scene has no geometry to cast shadows";
    return "";
}

std::string dynamicShSkipReason(const scene::Scene& s, const profile::Profile& p) {
    if (p.gi.dynamic != profile::GiDynamic::Sh) return "";
    if (!findDynamicObjects(s).objects.empty()) return "";
    return "gi.dynamic=sh but the scene has no dynamic objects (no SH textures; the frame runs "
           "as gi.dynamic=per_pixel, which is the same image without dynamic pixels)";
}

std::vector<SkippedWork> omittedVolumes(const probes::ProbeSet& set, const std::vector<int>& kept,
                                        const std::string& volumeLod) {
    std::vector<SkippedWork> out;
    for (size_t v = 0; v < set.volumes.size(); ++v) {
        if (std::find(kept.begin(), kept.end(), int(v)) != kept.end()) continue;
        const probes::ProbeVolume& vol = set.volumes[v];
        char what[200];
        std::snprintf(what, sizeof what, "volume '%s' (%.3f MiB of probe textures)",
                      vol.name.c_str(), double(profile::gpuVolumeBytes(set, v)) / (1024.0 * 1024.0));
        std::string why = "gi.volume_lod=" + volumeLod;
        auto parent =
            std::find_if(set.volumes.begin(), set.volumes.end(),
                         [&](const probes::ProbeVolume& p) { return p.name == vol.parent; });
        if (parent != set.volumes.end() &&
            std::find(kept.begin(), kept.end(), int(parent - set.volumes.begin())) == kept.end())
            why += " (its parent '" + vol.parent + "' is left out)";
        out.push_back({what, why + "; never uploaded"});
    }
    return out;
}

std::string skippedLine(const SkippedWork& s) {
    return "skipped " + s.what + ": " + s.why;
}

} // namespace pb::render
