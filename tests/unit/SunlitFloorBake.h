#pragma once
// The small bake request the probe-file and SH tests share: one 4x2x4 volume over
// pb::test::sunlitFloor() (ProbeTestScenes.h), scenarios "day" and "night", 64 rays. Callers
// change what their test needs (format, rays, bounces, extra scenarios).
#include "probes/bake/Baker.h"
#include "scene/Scene.h"

namespace pb::test {

inline probes::BakeRequest sunlitFloorRequest(const scene::Scene& s) {
    probes::BakeRequest r;
    probes::ProbeVolume v;
    v.name = "v";
    v.center = {0, 1, 0};
    v.halfExtents = {2, 0.9f, 2};
    v.counts = {4, 2, 4};
    r.volumes = {v};
    r.scenarios = probes::resolveScenarios({"day", "night"}, {}, s);
    r.settings.raysPerProbe = 64;
    return r;
}

} // namespace pb::test
