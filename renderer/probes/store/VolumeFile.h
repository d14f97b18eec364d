#pragma once
// The volumes file (`bake --volumes F.toml`): probe volumes and optional lighting scenarios.
//
//   [[volume]]
//   name = "hall"                    # required, unique
//   center = [0.0, 2.5, 0.0]         # required, world units
//   half_extents = [8.0, 2.5, 4.0]   # required, > 0 (the box is centre +- half_extents)
//   probes = [17, 6, 9]              # required, probes per local axis, each >= 1
//   rotation = [0.0, 30.0, 0.0]      # optional, Euler degrees: world = Ry * Rx * Rz * local
//   quaternion = [0.0, 0.0, 0.0, 1.0]  # optional instead of rotation: x, y, z, w
//   parent = "world"                 # optional; the child must lie inside the parent
//   edge_blend = 1.0                 # optional (children), see NestingBlend.h
//
//   [[scenario]]                     # optional; presets day/night exist without this
//   name = "dusk"
//   sun = { direction = [-0.8, 0.2, 0.1], intensity = 1.5, color = [1.0, 0.6, 0.4] }
//   # or sun = "off"; colour defaults to white; direction points towards the sun
//   sky = [0.10, 0.08, 0.12]         # constant sky radiance; omitted = the scene's
//
// Every error is one line "FILE:LINE: problem", naming the key (unknown keys are errors, so
// a typo never silently falls back to a default).
#include "probes/ProbeVolume.h"
#include "probes/Scenario.h"

#include <string>
#include <string_view>
#include <vector>

namespace pb::probes {

struct VolumeFile {
    std::vector<ProbeVolume> volumes;
    std::vector<ScenarioSpec> scenarios;
};

VolumeFile loadVolumeFile(const std::string& path);
// `path` only names the source in errors.
VolumeFile parseVolumeToml(std::string_view text, const std::string& path);

// The volumes as a volumes file (no scenarios) that parseVolumeToml reads back to the same
// volumes: numbers are written in the shortest form that parses back to the same float, an
// identity rotation is omitted, any other is written as `quaternion` (normalised again on
// reading, so only axis-aligned volumes - what `--volumes auto` writes - are bit-exact).
// `header` lines (may be empty) become `#` comments at the top.
std::string volumeFileText(const std::vector<ProbeVolume>& volumes, const std::string& header = "");
// volumeFileText written atomically (no partial file on error).
void writeVolumeFile(const std::string& path, const std::vector<ProbeVolume>& volumes,
                     const std::string& header = "");

} // namespace pb::probes
