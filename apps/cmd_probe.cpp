// probebench probe: the CPU reference sampler at one point of a baked probe file.
#include "CommandRegistry.h"
#include "JsonOption.h"
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
    JsonOption json;
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

// Whether a lookup found light to report, and if not, why (issue 18: a point between sparse
// storage's surface probes used to print E = 0 as if it had been measured).
struct LookupFound {
    bool found = true;
    std::string reason;
    int notStored = 0, invalid = 0, outsideGrid = 0; // of the 8 corners, when not found
};

LookupFound lookupFound(const ProbeSet& set, const ProbeSampler& sampler,
                        const IrradianceSample& r, const glm::vec3& at, const glm::vec3& normal,
                        const glm::vec3& view) {
    LookupFound f;
    if (r.volume < 0) {
        f.found = false;
        f.reason = "outside every volume (the renderer falls back to its ambient)";
        return f;
    }
    if (r.probes > 0 && r.weight > 0.0f) return f;
    f.found = false;
    if (r.probes > 0) {
        f.reason = "volume '" + set.volumes[size_t(r.volume)].name +
                   "' faded out at its edge (weight 0)";
        return f;
    }
    SampleTrace trace;
    sampler.sampleVolume(r.volume, at, normal, view, {}, &trace);
    const ProbeVolume& v = set.volumes[size_t(r.volume)];
    for (const CornerFetch& c : trace.corners) {
        if (!c.inGrid) {
            ++f.outsideGrid;
            continue;
        }
        const ProbeState& st = set.states[size_t(r.volume)][size_t(v.probeIndex(c.probe))];
        if (!ownsIrradiance(st)) ++f.notStored;
        else if (!st.valid) ++f.invalid;
    }
    f.reason = "none of the 8 probes around the point in volume '" + v.name + "' holds light (" +
               std::to_string(f.notStored) + " not stored and inside geometry, so no stand-in "
               "fills them; " + std::to_string(f.invalid) + " invalid: inside geometry; " +
               std::to_string(f.outsideGrid) + " outside the grid)";
    return f;
}

int runProbe(const ProbeArgs& a) {
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
    const LookupFound found = lookupFound(set, sampler, r, at, normal, view);
    if (a.json) {
        nlohmann::json j{{"probes_file", a.probes},
                         {"scenario", set.scenarios[size_t(scenario)].name},
                         {"at", vecJson(at)},
                         {"normal", vecJson(normal)},
                         {"eye_dir", vecJson(view)},
                         {"found", found.found},
                         {"irradiance", found.found ? vecJson(r.irradiance) : nlohmann::json()},
                         {"weight", r.weight},
                         {"volume", r.volume >= 0 ? nlohmann::json(volume) : nlohmann::json()},
                         {"probes_used", r.probes},
                         {"stand_ins", r.filled},
                         {"irradiance_only", r.irradianceOnly}};
        if (!found.found)
            j["not_found"] = {{"reason", found.reason},
                              {"corners_not_stored", found.notStored},
                              {"corners_invalid", found.invalid},
                              {"corners_outside_grid", found.outsideGrid}};
        writeJson(a.json, j.dump(2) + "\n");
        return 0;
    }
    if (!found.found) {
        std::printf("E: none - no probe found: %s\n", found.reason.c_str());
        return 0;
    }
    std::printf("E = %.6g %.6g %.6g  (irradiance, linear; a uniform sky L gives pi*L)\n",
                r.irradiance.x, r.irradiance.y, r.irradiance.z);
    if (r.volume >= 0) {
        std::printf("volume '%s', weight %.4g, %d probe(s)", volume.c_str(), r.weight, r.probes);
        if (r.filled > 0)
            std::printf(" (%d of them stand-ins for absent probes: their nearest stored probe)",
                        r.filled);
        if (r.irradianceOnly > 0)
            std::printf(" (%d of them irradiance-only: no surface nearby, read without visibility)",
                        r.irradianceOnly);
        std::printf(", scenario '%s'\n", set.scenarios[size_t(scenario)].name.c_str());
    }
    return 0;
}

const RegisterCommand registerProbe{{
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
        a->json.add(cmd, "The sample");
        return [a] { return runProbe(*a); };
    },
}};

} // namespace
} // namespace pb::app
