#include "ProbeOptions.h"

#include "probes/bake/SceneMatch.h"
#include "core/Error.h"
#include "probes/sh/ShSampler.h"
#include "probes/store/VolumeRanksFile.h"

namespace pb::app {

void addForceProbesFlag(CLI::App& cmd, bool& force) {
    cmd.add_flag("--force", force,
                 "Use --probes even when it was not baked for this scene (its input hash "
                 "differs: another scene, nodes baked as --dynamic that are static now, an older "
                 "bake)");
}

probes::ProbeSet readProbesForScene(const std::string& path, const scene::Scene& scene,
                                    bool force) {
    probes::ProbeSet set = probes::readProbeFileWithRanks(path);
    probes::requireProbesForScene(path, set, scene, force);
    return set;
}

void requireTechniqueData(const std::string& path, const probes::ProbeSet& set,
                          const profile::Profile& p) {
    if (p.gi.technique != profile::GiTechnique::Ddgi && !set.hasSh())
        throw Error(probes::noShMessage(path));
}

} // namespace pb::app
