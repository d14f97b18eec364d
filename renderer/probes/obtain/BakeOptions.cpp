#include "BakeOptions.h"

#include "probes/store/VolumeFile.h"

namespace pb::probes {

bool storesSparse(const BakeOptions& o) {
    AutoMode mode = AutoMode::Uniform;
    const bool adaptive = parseAutoMode(o.volumes, mode) && mode == AutoMode::Adaptive;
    return o.sparse || (adaptive && !o.dense);
}

AutoPlacementRequest autoPlacementRequest(const BakeOptions& o, const scene::Scene& s,
                                          AutoMode mode) {
    AutoPlacementRequest req;
    req.mode = mode;
    req.adaptive.spacing = o.spacing;
    req.adaptive.levels = o.autoLevels;
    req.adaptive.maxChildren = o.autoMaxChildren;
    req.adaptive.threads = o.threads;
    req.budgetBytes = o.budgetMib * 1024.0 * 1024.0;
    req.format = o.settings.format;
    req.sparse = storesSparse(o);
    req.freeSpace = req.sparse ? o.freeSpace : FreeSpace::StandIns;
    req.latticeSearch = o.latticeSearch;
    req.lighting = resolveScenarios(o.scenarios, {}, s).front();
    req.bounces = o.settings.bounces;
    return req;
}

void setBakeSettings(const BakeOptions& o, const scene::Scene& s,
                     const std::vector<ScenarioSpec>& fileScenarios, BakeRequest& r) {
    r.scenarios = resolveScenarios(o.scenarios, fileScenarios, s);
    r.settings = o.settings;
    r.threads = o.threads;
    r.sparse = storesSparse(o);
    r.freeSpace = r.sparse ? o.freeSpace : FreeSpace::StandIns;
    // Ranked tiles fill the budget; automatic placement sets its own (the default one too).
    r.freeSpaceBudgetBytes = o.budgetMib * 1024.0 * 1024.0;
}

std::size_t scenarioCountBeforePlacement(const BakeOptions& o, const scene::Scene& s) {
    AutoMode mode;
    if (parseAutoMode(o.volumes, mode)) return resolveScenarios(o.scenarios, {}, s).size();
    return resolveScenarios(o.scenarios, loadVolumeFile(o.volumes).scenarios, s).size();
}

} // namespace pb::probes
