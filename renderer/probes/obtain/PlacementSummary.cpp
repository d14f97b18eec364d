#include "PlacementSummary.h"

#include "probes/ProbeVolume.h"

#include <algorithm>

namespace pb::probes {
namespace {

// Nesting depth of each volume (0 = root).
std::vector<int> volumeDepths(const std::vector<ProbeVolume>& volumes) {
    std::vector<int> parents = validateVolumes(volumes, "placement"), depth(volumes.size(), 0);
    for (size_t i = 0; i < volumes.size(); ++i)
        for (int p = parents[i]; p >= 0; p = parents[size_t(p)])
            ++depth[i];
    return depth;
}

} // namespace

nlohmann::json placementJson(const PlacementInfo& p, StorageFormat format) {
    std::vector<int> depth = volumeDepths(p.result.volumes);
    nlohmann::json tiers = nlohmann::json::array();
    for (size_t i = 0; i < p.result.volumes.size(); ++i) {
        if (size_t(depth[i]) >= tiers.size())
            tiers.push_back({{"volumes", 0}, {"probes", 0}, {"spacing", 0.0}});
        auto& t = tiers[size_t(depth[i])];
        const ProbeVolume& v = p.result.volumes[i];
        glm::vec3 c = v.cellSize();
        t["volumes"] = t["volumes"].get<int>() + 1;
        t["probes"] = t["probes"].get<long long>() + v.probeCount();
        t["spacing"] = std::max(c.x, std::max(c.y, c.z));
    }
    nlohmann::json j{{"mode", p.mode},
                     {"tiers", tiers},
                     {"probes", p.result.probes},
                     {"bytes", p.result.bytes},
                     {"budget_bytes", p.result.budgetBytes},
                     {"default_budget", p.result.defaultBudget},
                     {"format", formatName(format)},
                     {"storage", p.sparse ? "sparse" : "dense"},
                     {"notes", p.result.notes}};
    if (p.result.latticeSearched) {
        const LatticeShift& l = p.result.latticeShift;
        j["lattice_search"] = {{"shift_cells", {l.cells.x, l.cells.y, l.cells.z}},
                               {"estimated_error_before", l.errorBefore},
                               {"estimated_error_after", l.errorAfter},
                               {"trials", l.trials},
                               {"seconds", p.result.latticeSearchSeconds}};
    }
    if (p.mode == "adaptive") {
        j["corner_rays"] = p.result.stats.rays;
        j["cells_tested"] = p.result.stats.cellsTested;
        j["cells_near_surfaces"] = p.result.stats.cellsNear;
        j["placements"] = p.result.placements;
    }
    return j;
}

} // namespace pb::probes
