#pragma once
// Probe sets built in code for the cost-model tests: every probe sees no surface (visibility
// mean = meanSq = 1: nothing occludes), irradiance 1 everywhere, one scenario "day", all
// probes valid and stored. Tests then mark probes invalid or absent as they need.
#include "probes/ProbeSet.h"

#include <algorithm>
#include <vector>

namespace pb::test {

inline probes::ProbeVolume gridVolume(const char* name, glm::vec3 center, glm::vec3 halfExtents,
                                      glm::ivec3 counts) {
    probes::ProbeVolume v;
    v.name = name;
    v.center = center;
    v.halfExtents = halfExtents;
    v.counts = counts;
    return v;
}

inline probes::ProbeSet openProbeSet(const std::vector<probes::ProbeVolume>& volumes) {
    probes::ProbeSet set;
    set.scenarios.push_back({"day", {}, {}});
    set.irradiance.emplace_back();
    for (const probes::ProbeVolume& v : volumes) {
        set.volumes.push_back(v);
        set.states.emplace_back(size_t(v.probeCount()));
        probes::ProbeTexture vis = probes::ProbeTexture::make(probes::visibilityShape(v.counts));
        std::fill(vis.texels.begin(), vis.texels.end(), 1.0f);
        set.visibility.push_back(vis);
        probes::ProbeTexture irr = probes::ProbeTexture::make(probes::irradianceShape(v.counts));
        std::fill(irr.texels.begin(), irr.texels.end(), 1.0f);
        set.irradiance[0].push_back(irr);
    }
    return set;
}

} // namespace pb::test
