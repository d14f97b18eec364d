#include "probes/bake/SceneMatch.h"

#include "probes/bake/RebuiltRequest.h"

#include "core/Error.h"
#include "probes/bake/Baker.h"

#include <cstdio>

namespace pb::probes {

bool probeSetMatchesScene(const ProbeSet& set, const scene::Scene& scene) {
    auto matches = [&](const scene::Scene& candidate) {
        return rebuiltBakeRequest(candidate, set).has_value();
    };
    if (matches(scene)) return true;
    // Nodes marked --dynamic now but baked static: the same scene, probes that include them
    // (rendering a node through the dynamic path against such probes is a normal experiment).
    bool anyDynamic = false;
    for (const scene::Instance& i : scene.instances)
        anyDynamic = anyDynamic || i.dynamic;
    if (!anyDynamic) return false;
    scene::Scene allStatic = scene;
    for (scene::Instance& i : allStatic.instances)
        i.dynamic = false;
    return matches(allStatic);
}

void requireProbesForScene(const std::string& path, const ProbeSet& set,
                           const scene::Scene& scene, bool force) {
    if (force || probeSetMatchesScene(set, scene)) return;
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(set.inputHash));
    throw fileError(path, "not baked for scene '" + scene.name + "' as loaded (input hash " +
                              hash + " differs: another scene, nodes baked as --dynamic that "
                                     "are static now, or an older bake); bake it for this "
                                     "scene, or --force to use it anyway");
}

} // namespace pb::probes
