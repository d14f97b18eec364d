#pragma once
// Lighting scenarios: named sun + sky settings baked from one geometry into separate
// irradiance data sets of one probe file (the talk's day/night versions of a map).
// Punctual lights and emissive materials are part of the scene and shared by all scenarios.
//
// Built-in presets:
//   day   - the scene's own sun and sky (after --sun / --sky overrides)
//   night - sun off, sky radiance kNightSky (a faint blue); lights and emissives unchanged
// A volumes TOML file may define more ([[scenario]], see VolumeFile.h); a name defined there
// wins over a preset of the same name.
#include "scene/Scene.h"

#include <optional>
#include <string>
#include <vector>

namespace pb::probes {

inline constexpr glm::vec3 kNightSky{0.004f, 0.006f, 0.012f};

struct Scenario {
    std::string name;
    scene::Sun sun;
    scene::Sky sky;
};

// A scenario as written in a TOML file: unset parts take the scene's values.
struct ScenarioSpec {
    std::string name;
    std::optional<scene::Sun> sun;
    std::optional<scene::Sky> sky;
};

const std::vector<std::string>& presetScenarioNames();

// Resolves `names` (default {"day"} when empty) against the file's specs, then the presets.
// Throws pb::Error listing the available names for an unknown one, or on a duplicate.
std::vector<Scenario> resolveScenarios(const std::vector<std::string>& names,
                                       const std::vector<ScenarioSpec>& fromFile,
                                       const scene::Scene& scene);

} // namespace pb::probes
