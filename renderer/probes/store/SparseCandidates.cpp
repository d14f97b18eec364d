#include "probes/store/SparseCandidates.h"

namespace pb::probes {

bool probeSeesNoSurface(const ProbeTexture& visibility, const glm::ivec3& c) {
    for (int row = 1; row <= kVisibilityInterior; ++row)
        for (int col = 1; col <= kVisibilityInterior; ++col) {
            const float* t =
                visibility.at(c.x * kVisibilityTile + col, c.z * kVisibilityTile + row, c.y);
            if (!(t[0] >= kFarVisibility)) return false;
        }
    return true;
}

std::vector<SparseCounts> countSparseCandidates(const ProbeSet& set) {
    std::vector<SparseCounts> out(set.volumes.size());
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        const ProbeVolume& vol = set.volumes[v];
        if (v >= set.states.size() || v >= set.visibility.size()) continue;
        const ProbeTexture& vis = set.visibility[v];
        if (vis.shape != visibilityShape(vol.counts) || vis.texels.size() != vis.shape.floatCount())
            continue;
        for (int i = 0; i < vol.probeCount(); ++i) {
            if (!set.states[v][size_t(i)].valid)
                ++out[v].invalid;
            else if (probeSeesNoSurface(vis, vol.probeCoords(i)))
                ++out[v].far;
        }
    }
    return out;
}

} // namespace pb::probes
