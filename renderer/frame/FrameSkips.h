#pragma once
// What a frame leaves out because the scene, the profile or the view does not need it, and why
// (renderer/README.md "What the frame skips"). FrameRenderer decides with these functions;
// `probebench render --verbose` prints the result, one line per skipped pass or resource.
// Every skip leaves the image unchanged: a skipped pass would have added exactly nothing.
#include "probes/ProbeSet.h"
#include "profile/Profile.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace pb::render {

struct SkippedWork {
    std::string what; // "pass shadow", "volume 'attic' (0.52 MiB of probe textures)", ...
    std::string why;
};

// "" when the scene has a light the shadow pass draws a map for, else why there is none. Only
// the sun casts shadows today (punctual lights are unshadowed), so: sun off, a sun of zero
// irradiance (its term adds exactly 0), or nothing to draw (empty bounds).
std::string shadowSkipReason(const scene::Scene& s);

// "" unless gi.dynamic=sh asks for an SH pass the scene cannot use (no dynamic objects: no
// pixel reads the coefficients).
std::string dynamicShSkipReason(const scene::Scene& s, const profile::Profile& p);

// One entry per volume gi.volume_lod leaves out (never uploaded), with the GPU bytes it saves.
// kept: file indices of the loaded volumes (selectVolumes).
std::vector<SkippedWork> omittedVolumes(const probes::ProbeSet& set, const std::vector<int>& kept,
                                        const std::string& volumeLod);

// "skipped pass shadow: the sun is off ..." - the line `render --verbose` prints.
std::string skippedLine(const SkippedWork& s);

} // namespace pb::render
