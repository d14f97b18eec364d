#include "studies/common/StudyBake.h"

#include "probes/bake/Baker.h"

namespace pb::studies {

probes::ProbeSet bake(const scene::Scene& scene, const BakeOptions& options) {
    probes::BakeRequest request;
    request.volumes = options.volumes;
    request.scenarios = probes::resolveScenarios(options.scenarios, {}, scene);
    request.settings.raysPerProbe = options.rays;
    request.settings.bounces = options.bounces;
    request.settings.noiseTarget = options.noiseTarget;
    request.threads = options.threads;
    request.sparse = options.sparse;
    request.freeSpace = options.freeSpace;
    request.freeSpaceBudgetBytes = options.freeSpaceBudgetBytes;
    return probes::bakeProbes(scene, request);
}

} // namespace pb::studies
