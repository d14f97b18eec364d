#include "probes/Scenario.h"

#include "core/Error.h"

#include <algorithm>

namespace pb::probes {

const std::vector<std::string>& presetScenarioNames() {
    static const std::vector<std::string> names{"day", "night"};
    return names;
}

namespace {
Scenario fromSpec(const ScenarioSpec& s, const scene::Scene& scene) {
    Scenario out{s.name, scene.sun, scene.sky};
    if (s.sun) out.sun = *s.sun;
    if (s.sky) out.sky = *s.sky;
    return out;
}

Scenario preset(const std::string& name, const scene::Scene& scene) {
    Scenario s{name, scene.sun, scene.sky};
    if (name == "night") {
        s.sun.enabled = false;
        s.sky.radiance = kNightSky;
    }
    return s;
}
} // namespace

std::vector<Scenario> resolveScenarios(const std::vector<std::string>& requested,
                                       const std::vector<ScenarioSpec>& fromFile,
                                       const scene::Scene& scene) {
    std::vector<std::string> names = requested;
    if (names.empty()) names.push_back("day");
    std::vector<Scenario> out;
    for (const std::string& n : names) {
        for (const Scenario& s : out)
            if (s.name == n) throw Error("--scenario: '" + n + "' given twice");
        auto spec = std::find_if(fromFile.begin(), fromFile.end(),
                                 [&](const ScenarioSpec& s) { return s.name == n; });
        if (spec != fromFile.end()) {
            out.push_back(fromSpec(*spec, scene));
            continue;
        }
        const auto& presets = presetScenarioNames();
        if (std::find(presets.begin(), presets.end(), n) != presets.end()) {
            out.push_back(preset(n, scene));
            continue;
        }
        std::string known;
        for (const auto& s : fromFile)
            known += (known.empty() ? "" : ", ") + s.name;
        for (const auto& p : presets)
            known += (known.empty() ? "" : ", ") + p;
        throw Error("--scenario: unknown scenario '" + n + "' (available: " + known + ")");
    }
    return out;
}

} // namespace pb::probes
