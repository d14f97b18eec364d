#include "RebuiltRequest.h"

namespace pb::probes {

std::optional<BakeRequest> rebuiltBakeRequest(const scene::Scene& scene, const ProbeSet& set,
                                              std::string* why) {
    BakeRequest r;
    r.volumes = set.volumes;
    r.scenarios = set.scenarios;
    r.settings = set.settings;
    r.freeSpace = set.freeSpace;
    r.freeSpaceBudgetBytes = set.freeSpaceBudgetBytes;
    // A dense set records StandIns; a sparse one may too (`bake --free-space none`), so the
    // storage is the one thing to try both ways.
    for (const bool sparse : {set.freeSpace != FreeSpace::StandIns, set.freeSpace == FreeSpace::StandIns}) {
        r.sparse = sparse;
        if (bakeInputHash(scene, r) == set.inputHash) return r;
    }
    if (why)
        *why = "the probes' input hash is not this scene's with their own settings (baked for "
               "another scene, or by an older bake)";
    return std::nullopt;
}

} // namespace pb::probes
