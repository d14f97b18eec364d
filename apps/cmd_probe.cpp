// probebench probe: the CPU reference sampler at one point of a baked probe file.
#include "CommandRegistry.h"
#include "core/Error.h"
#include "probes/store/ProbeFile.h"
#include "probes/ProbeSampler.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace pb::app {
namespace {

using namespace pb::probes;

struct ProbeArgs {
    std::string probes, at, normal, eyeDir, scenario;
    bool json = false;
};

glm::vec3 parseVec3(const std::string& text, const std::string& option, bool nonZero) {
    std::stringstream ss(text);
    glm::vec3 v;
    char c1 = 0, c2 = 0;
    if (!(ss >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' ||
        !(ss >> std::ws).eof() || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw Error(option + ": expected X,Y,Z (got '" + text + "')");
    if (nonZero && !(glm::length(v) > 0.0f)) throw Error(option + ": must not be zero");
    return v;
}

nlohmann::json vecJson(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

int run(const ProbeArgs& a) {
    glm::vec3 at = parseVec3(a.at, "--at", false);
    glm::vec3 normal = glm::normalize(parseVec3(a.normal, "--normal", true));
    glm::vec3 view =
        a.eyeDir.empty() ? normal : glm::normalize(parseVec3(a.eyeDir, "--eye-dir", true));
    ProbeSet set = readProbeFile(a.probes);
    int scenario = 0;
    if (!a.scenario.empty()) {
        scenario = set.findScenario(a.scenario);
        if (scenario < 0) {
            std::string names;
            for (const auto& s : set.scenarios)
                names += (names.empty() ? "" : ", ") + s.name;
            throw Error("--scenario: '" + a.scenario + "' is not in " + a.probes + " (" + names +
                        ")");
        }
    }
    ProbeSampler sampler(set, scenario);
    IrradianceSample r = sampler.sample(at, normal, view);
    std::string volume = r.volume >= 0 ? set.volumes[size_t(r.volume)].name : "";
    // A lookup that read no probe is no measurement: E = 0 would read as darkness. Say why
    // instead (issue 18); the renderer blends its ambient there.
    const bool found = r.weight > 0.0f;
    std::string reason;
    if (r.volume < 0)
        reason = "outside every volume";
    else if (r.probes == 0)
        reason = "no valid probe around the point in volume '" + volume + "'";
    else if (!found)
        reason = "beyond the edge fade of volume '" + volume + "'";
    if (a.json) {
        nlohmann::json j{{"probes_file", a.probes},
                         {"scenario", set.scenarios[size_t(scenario)].name},
                         {"at", vecJson(at)},
                         {"normal", vecJson(normal)},
                         {"eye_dir", vecJson(view)},
                         {"found", found},
                         {"irradiance", found ? vecJson(r.irradiance) : nlohmann::json()},
                         {"weight", r.weight},
                         {"volume", r.volume >= 0 ? nlohmann::json(volume) : nlohmann::json()},
                         {"probes_used", r.probes},
                         {"stand_ins", r.filled}};
        if (!found) j["reason"] = reason;
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    if (!found) {
        std::printf("no stored probe found: %s (no irradiance; the renderer falls back to its "
                    "ambient)\n",
                    reason.c_str());
        return 0;
    }
    std::printf("E = %.6g %.6g %.6g  (irradiance, linear; a uniform sky L gives pi*L)\n",
                r.irradiance.x, r.irradiance.y, r.irradiance.z);
    std::printf("volume '%s', weight %.4g, %d probe(s)", volume.c_str(), r.weight, r.probes);
    if (r.filled > 0)
        std::printf(" (%d of them stand-ins for absent probes: their nearest stored probe)",
                    r.filled);
    std::printf(", scenario '%s'\n", set.scenarios[size_t(scenario)].name.c_str());
    return 0;
}

const RegisterCommand reg{{
    "probe",
    "Irradiance from a probe file at one point (the CPU reference sampler)",
    40,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<ProbeArgs>();
        cmd.add_option("--probes", a->probes, "Probe file written by `probebench bake`")
            ->required();
        cmd.add_option("--at", a->at, "World position X,Y,Z")->required();
        cmd.add_option("--normal", a->normal, "Surface normal X,Y,Z")->required();
        // Not --view: everywhere else that names a view of the scene (issue 25, item 9).
        cmd.add_option("--eye-dir", a->eyeDir,
                       "Direction from the point towards the viewer X,Y,Z "
                       "(default: the normal)");
        cmd.add_option("--scenario", a->scenario, "Lighting scenario (default: the first)");
        cmd.add_flag("--json", a->json, "Print JSON");
        return [a] { return run(*a); };
    },
}};

} // namespace
} // namespace pb::app
