#pragma once
// `probebench render --debug NAME`: what a GI debug view shows (renderer/README.md "Debug
// views"). GL-free names and parsing; FrameRenderer wires each to its pass or setting.
#include <string>
#include <vector>

namespace pb::render {

enum class GiDebugView {
    None,
    GiOnly,           // the indirect term alone: albedo / pi x GI irradiance
    ProbesIrradiance, // a sphere per probe, a white Lambertian lit by the probe's irradiance
    ProbesVisibility, // a sphere per probe, brightness = mean free distance, black = invalid
    VolumeCoverage,   // which volume shaded each pixel, and full evaluations per pixel
};

const std::vector<std::string>& giDebugViewNames(); // the names, None excluded
const char* giDebugViewName(GiDebugView v);         // "" for None
// Throws pb::Error "--debug 'x': unknown debug view (views: ...)".
GiDebugView parseGiDebugView(const std::string& name);

} // namespace pb::render
