#include "costmodel/GiVolumeLod.h"

#include "core/Error.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace pb::render {

std::size_t gpuVolumeBytes(const probes::ProbeVolume& v, probes::StorageFormat format) {
    return probes::storedBytes(probes::irradianceShape(v.counts), format) +
           probes::storedBytes(probes::visibilityShape(v.counts), format) +
           std::size_t(v.probeCount()) * 16;
}

namespace {

// keep[v] = false for every volume with an omitted ancestor (parents come first in `order`).
void dropOrphans(const std::vector<int>& parents, std::vector<bool>& keep) {
    for (int v : probes::parentFirstOrder(parents))
        if (parents[size_t(v)] >= 0 && !keep[size_t(parents[size_t(v)])]) keep[size_t(v)] = false;
}

} // namespace

std::vector<int> selectVolumes(const probes::ProbeSet& set, const profile::VolumeLod& lod) {
    using Mode = profile::VolumeLod::Mode;
    const std::vector<int> parents = probes::validateVolumes(set.volumes, "probe set");
    const size_t n = set.volumes.size();
    std::vector<bool> keep(n, true);
    if (lod.mode == Mode::Omit) {
        for (const std::string& name : lod.names) {
            auto it = std::find_if(set.volumes.begin(), set.volumes.end(),
                                   [&](const probes::ProbeVolume& v) { return v.name == name; });
            if (it == set.volumes.end())
                throw Error("gi.volume_lod: no volume named '" + name + "' in the probe set");
            keep[size_t(it - set.volumes.begin())] = false;
        }
    } else if (lod.mode == Mode::MinSpacing) {
        for (size_t v = 0; v < n; ++v)
            keep[v] = set.volumes[v].minCellSize() >= float(lod.value);
    } else if (lod.mode == Mode::BudgetMiB) {
        // Coarsest first (roots before their children at equal spacing): detail goes first.
        std::vector<int> order = probes::parentFirstOrder(parents);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return set.volumes[size_t(a)].minCellSize() > set.volumes[size_t(b)].minCellSize();
        });
        const double budget = lod.value * 1024.0 * 1024.0;
        double used = 0;
        std::fill(keep.begin(), keep.end(), false);
        for (int v : order) {
            const int parent = parents[size_t(v)];
            if (parent >= 0 && !keep[size_t(parent)]) continue;
            double bytes = double(gpuVolumeBytes(set.volumes[size_t(v)], set.format()));
            if (used + bytes <= budget) {
                keep[size_t(v)] = true;
                used += bytes;
            } else if (parent < 0) {
                std::ostringstream msg;
                msg << "gi.volume_lod=budget_mib:" << lod.value << ": root volume '"
                    << set.volumes[size_t(v)].name << "' needs " << bytes / (1024.0 * 1024.0)
                    << " MiB more than fits";
                throw Error(msg.str());
            }
        }
    }
    dropOrphans(parents, keep);
    std::vector<int> out;
    for (size_t v = 0; v < n; ++v)
        if (keep[v]) out.push_back(int(v));
    return out;
}

std::vector<int> volumeDrawOrder(const std::vector<float>& boxVolumes,
                                 const std::vector<int>& fileIndices) {
    std::vector<int> order(fileIndices.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        const float va = boxVolumes[size_t(a)], vb = boxVolumes[size_t(b)];
        if (va != vb) return va > vb;
        return fileIndices[size_t(a)] > fileIndices[size_t(b)];
    });
    return order;
}

} // namespace pb::render
