#include "VolumeLodLevels.h"

#include "core/Error.h"
#include "profile/GiVolumeLod.h"
#include "profile/VolumeLod.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace pb::bench {

std::vector<std::string> volumeLodLevels(const probes::ProbeSet& set) {
    std::vector<std::string> out;
    std::set<std::vector<int>> seen;
    auto consider = [&](const std::string& lod) {
        std::vector<int> kept;
        try {
            kept = profile::selectVolumes(set, profile::parseVolumeLod(lod));
        } catch (const Error&) {
            return; // e.g. a level that keeps no volume
        }
        if (!kept.empty() && seen.insert(kept).second) out.push_back(lod);
    };
    consider("all");
    std::vector<float> spacings;
    for (const probes::ProbeVolume& v : set.volumes)
        spacings.push_back(v.minCellSize());
    std::sort(spacings.begin(), spacings.end());
    char buf[64];
    for (float s : spacings) {
        std::snprintf(buf, sizeof buf, "min_spacing:%.9g", double(s));
        consider(buf);
    }
    if (set.ranks)
        for (const profile::RankDropStep& step : profile::rankDropOrder(set)) {
            if (step.keptBytes == 0) continue;
            // Rounded up to the micro-MiB: the level keeps exactly what the step keeps.
            const double mib = std::ceil(double(step.keptBytes) / 1048576.0 * 1e6) / 1e6;
            std::snprintf(buf, sizeof buf, "rank_budget_mib:%.6f", mib);
            consider(buf);
        }
    return out;
}

} // namespace pb::bench
