#pragma once
// Small in-memory bakes of a built-in scene for the GI GL tests (seconds on 2 cores): the
// auto root volume over `rooms` plus a rotated child volume nested in it, so volume choice,
// edge fade, relocation and invalid probes are all exercised. Cached per format per process.
#include "probes/placement/AutoVolume.h"
#include "probes/bake/Baker.h"
#include "raytrace/RayScene.h"
#include "probes/Scenario.h"
#include "scene/SceneLoader.h"

#include <map>
#include <memory>

namespace pb::test {

inline const scene::Scene& giTestScene() {
    static const scene::Scene s = scene::makeBuiltinScene("rooms");
    return s;
}

inline const probes::ProbeSet& giTestProbes(probes::StorageFormat format) {
    static std::map<probes::StorageFormat, std::unique_ptr<probes::ProbeSet>> cache;
    auto& slot = cache[format];
    if (!slot) {
        const scene::Scene& s = giTestScene();
        probes::BakeRequest r;
        probes::AutoVolume root = probes::fitAutoVolume(raytrace::staticBakeBounds(s), 0.0f, 400);
        r.volumes.push_back(root.volume);
        probes::ProbeVolume child;
        child.name = "child";
        child.parent = root.volume.name;
        child.center = root.volume.center + glm::vec3(0.1f, 0.0f, -0.2f) * root.volume.halfExtents;
        child.halfExtents = root.volume.halfExtents * glm::vec3(0.35f, 0.6f, 0.35f);
        child.rotation = probes::rotationFromEulerDegrees({0.0f, 30.0f, 0.0f});
        child.counts = glm::ivec3(5, 3, 4);
        r.volumes.push_back(child);
        r.scenarios = probes::resolveScenarios({"day"}, {}, s);
        r.settings.raysPerProbe = 64;
        r.settings.bounces = 2;
        r.settings.format = format;
        slot = std::make_unique<probes::ProbeSet>(probes::bakeProbes(s, r));
        // rooms has no single-sided solids, so nothing bakes invalid: mark every 7th probe
        // invalid (both samplers must then skip it) to exercise the exclusion - as the bake
        // would, with a back-face ratio over the threshold (sparse storage then never fills
        // it in: probes/AbsentProbeFill.h).
        for (auto& states : slot->states)
            for (size_t p = 0; p < states.size(); p += 7) {
                states[p].valid = false;
                states[p].backfaceRatio = 1.0f;
            }
    }
    return *slot;
}

} // namespace pb::test
