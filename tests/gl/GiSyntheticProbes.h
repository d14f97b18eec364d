#pragma once
// Hand-made probe sets for GI GL tests whose answer is known without a bake: open visibility
// (mean = mean^2 = 1: nothing occludes, Chebyshev never attenuates) and an irradiance chosen
// per probe and local direction, quantised to the storage format as a bake would store it.
#include "probes/Octahedral.h"
#include "probes/ProbeSet.h"
#include "probes/StorageFormat.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::test {

// E(volume index, local direction, probe grid coordinates).
using SyntheticIrradiance = std::function<glm::vec3(int, const glm::vec3&, const glm::ivec3&)>;

inline probes::ProbeVolume syntheticVolume(const std::string& name, glm::vec3 center,
                                           glm::vec3 half, glm::ivec3 counts,
                                           const std::string& parent = "") {
    probes::ProbeVolume v;
    v.name = name;
    v.parent = parent;
    v.center = center;
    v.halfExtents = half;
    v.counts = counts;
    return v;
}

inline probes::ProbeSet syntheticProbes(const std::vector<probes::ProbeVolume>& volumes,
                                        const SyntheticIrradiance& irradiance,
                                        probes::StorageFormat format) {
    using namespace probes;
    ProbeSet set;
    set.settings.format = format;
    set.volumes = volumes;
    set.scenarios.push_back({"synthetic", {}, {}});
    set.irradiance.emplace_back();
    for (size_t vi = 0; vi < volumes.size(); ++vi) {
        const ProbeVolume& v = volumes[vi];
        set.states.emplace_back(size_t(v.probeCount()));
        ProbeTexture vis = ProbeTexture::make(visibilityShape(v.counts));
        for (float& x : vis.texels)
            x = 1.0f;
        quantise(vis, format);
        set.visibility.push_back(std::move(vis));
        ProbeTexture irr = ProbeTexture::make(irradianceShape(v.counts));
        for (int p = 0; p < v.probeCount(); ++p) {
            const glm::ivec3 c = v.probeCoords(p);
            for (int j = 0; j < kIrradianceInterior; ++j)
                for (int i = 0; i < kIrradianceInterior; ++i) {
                    glm::vec3 e =
                        irradiance(int(vi), octTexelDirection(i, j, kIrradianceInterior), c);
                    float* t =
                        irr.at(c.x * kIrradianceTile + 1 + i, c.z * kIrradianceTile + 1 + j, c.y);
                    t[0] = e.x, t[1] = e.y, t[2] = e.z, t[3] = 1.0f;
                }
        }
        fillAllBorders(irr, kIrradianceInterior);
        quantise(irr, format);
        set.irradiance[0].push_back(std::move(irr));
    }
    return set;
}

} // namespace pb::test
