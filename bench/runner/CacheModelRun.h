#pragma once
// Fills the bench report's texture-cache section (report/CacheModelSection.h): for every
// session's profile, the cost model of the bench's view at the session's size, all four
// shader variants through the profile's cache preset. GL-free; seconds per profile at
// 512x288, minutes at 1440p on 2 cores (`probebench bench --no-cache-model` skips it).
#include "bench/report/AblationPlan.h"
#include "bench/report/CacheModelSection.h"
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include "views/WorstCaseView.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pb::bench {

// The cost model's coverage tester of the volumes gi.volume_lod `volumeLod` keeps (the one place
// the report's cache section and the device model build it).
std::unique_ptr<views::CoverageTester> keptVolumesTester(const scene::Scene& scene,
                                                         const probes::ProbeSet& set,
                                                         const std::string& volumeLod);

std::vector<CacheModelEntry>
cacheModelEntries(const BenchPlan& plan, const scene::Scene& scene, const probes::ProbeSet& set,
                  const scene::View& view,
                  const std::function<void(const std::string&)>& progress = {});

} // namespace pb::bench
