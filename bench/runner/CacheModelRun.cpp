#include "CacheModelRun.h"

#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "profile/GiVolumeLod.h"

#include <map>
#include <memory>

namespace pb::bench {

std::unique_ptr<views::CoverageTester> keptVolumesTester(const scene::Scene& scene,
                                                         const probes::ProbeSet& set,
                                                         const std::string& volumeLod) {
    std::vector<bool> kept(set.volumes.size(), false);
    for (int v : profile::selectVolumes(set, profile::parseVolumeLod(volumeLod)))
        kept[size_t(v)] = true;
    return std::make_unique<views::CoverageTester>(scene, set, kept);
}

std::vector<CacheModelEntry>
cacheModelEntries(const BenchPlan& plan, const scene::Scene& scene, const probes::ProbeSet& set,
                  const scene::View& view,
                  const std::function<void(const std::string&)>& progress) {
    std::map<std::string, std::unique_ptr<views::CoverageTester>> testers; // per volume_lod
    std::vector<CacheModelEntry> out;
    for (const Session& s : plan.sessions) {
        const profile::PlatformProfile& p = s.profile;
        if (progress) progress("texture-cache model of " + p.name);
        auto& tester = testers[p.switches.gi.volumeLod];
        if (!tester) tester = keptVolumesTester(scene, set, p.switches.gi.volumeLod);
        costmodel::CostModelOptions o;
        o.width = s.width;
        o.height = s.height;
        o.profile = p.switches;
        o.caches = {costmodel::cachePresetFor(p.cachePreset)};
        const costmodel::CostReport r = costmodel::runCostModel(*tester, view, o);
        CacheModelEntry e{p.name,           o.caches[0].name + ": " + o.caches[0].describe(),
                          s.width,          s.height,
                          r.profileVariant, {}};
        for (const costmodel::CacheResult& res : r.results)
            e.variants.push_back({res.variant, res.probeHitRate(),
                                  res.probeBytesMissedPerPixel(r.counters.giPixels)});
        out.push_back(e);
    }
    return out;
}

} // namespace pb::bench
