#include "profile/GiVolumeLod.h"

#include "core/Error.h"
#include "probes/store/SparseLayout.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace pb::profile {

std::size_t gpuVolumeBytes(const probes::ProbeVolume& v, probes::StorageFormat format) {
    return probes::storedBytes(probes::irradianceShape(v.counts), format) +
           probes::storedBytes(probes::visibilityShape(v.counts), format) +
           std::size_t(v.probeCount()) * 16;
}

std::size_t gpuVolumeBytes(const probes::ProbeSet& set, std::size_t v) {
    const probes::ProbeVolume& vol = set.volumes[v];
    if (v >= set.states.size() || !probes::isSparse(set.states[v]))
        return gpuVolumeBytes(vol, set.format());
    // As GpuProbes allocates: irradiance for the stored and irradiance-only tiles, visibility
    // for the stored ones.
    const probes::TileLayout tiles = probes::tileLayout(vol, set.states[v]);
    return probes::storedBytes(probes::irradianceShape(tiles.packedCounts), set.format()) +
           probes::storedBytes(probes::visibilityShape(tiles.visibilityPackedCounts),
                               set.format()) +
           std::size_t(vol.probeCount()) * probes::kStateBytesPerProbe;
}

namespace {

// keep[v] = false for every volume with an omitted ancestor (parents come first in `order`).
void dropOrphans(const std::vector<int>& parents, std::vector<bool>& keep) {
    for (int v : probes::parentFirstOrder(parents))
        if (parents[size_t(v)] >= 0 && !keep[size_t(parents[size_t(v)])]) keep[size_t(v)] = false;
}

// The subtree of v among the volumes still kept (v first).
std::vector<int> keptSubtree(const std::vector<int>& parents, const std::vector<bool>& keep,
                             int v) {
    std::vector<int> out{v};
    for (size_t i = 0; i < out.size(); ++i)
        for (size_t c = 0; c < parents.size(); ++c)
            if (parents[c] == out[i] && keep[c]) out.push_back(int(c));
    return out;
}

std::string mib(double bytes) {
    std::ostringstream s;
    s << bytes / (1024.0 * 1024.0);
    return s.str();
}

} // namespace

std::vector<RankDropStep> rankDropOrder(const probes::ProbeSet& set) {
    if (!set.ranks)
        throw Error("no volume ranks for this probe set (" + set.ranksNote +
                    "); rank it with `probebench volumes --rank --write-ranks`");
    const std::vector<int> parents = probes::validateVolumes(set.volumes, "probe set");
    const size_t n = set.volumes.size();
    std::vector<double> loss(n, 0.0);
    for (size_t v = 0; v < n; ++v) {
        const probes::VolumeRank* r = set.ranks->find(set.volumes[v].name);
        if (!r) throw Error("volume ranks: no rank for volume '" + set.volumes[v].name + "'");
        loss[v] = r->loss;
    }
    std::vector<std::size_t> bytes(n);
    std::size_t kept = 0;
    for (size_t v = 0; v < n; ++v)
        kept += bytes[v] = gpuVolumeBytes(set, size_t(v));
    std::vector<bool> keep(n, true);
    std::vector<RankDropStep> steps;
    while (kept > 0) {
        int best = -1;
        double bestValue = 0;
        for (size_t v = 0; v < n; ++v) {
            if (!keep[v] || keptSubtree(parents, keep, int(v)).size() > 1) continue; // not a leaf
            const double value = loss[v] / double(std::max<std::size_t>(bytes[v], 1));
            if (best < 0 || value < bestValue ||
                (value == bestValue && bytes[v] >= bytes[size_t(best)])) {
                best = int(v);
                bestValue = value;
            }
        }
        keep[size_t(best)] = false;
        kept -= bytes[size_t(best)];
        steps.push_back(RankDropStep{best, kept});
    }
    return steps;
}

std::vector<int> selectVolumes(const probes::ProbeSet& set, const VolumeLod& lod) {
    using Mode = VolumeLod::Mode;
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
            double bytes = double(gpuVolumeBytes(set, size_t(v)));
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
    } else if (lod.mode == Mode::RankBudgetMiB) {
        // Ranks are required even when everything fits: the profile must not depend on luck.
        const std::string form = "gi.volume_lod=rank_budget_mib:" + mib(lod.value * 1048576.0);
        std::vector<RankDropStep> steps;
        try {
            steps = rankDropOrder(set);
        } catch (const Error& e) {
            throw Error(form + ": " + e.what());
        }
        const double budget = lod.value * 1024.0 * 1024.0;
        std::size_t total = 0;
        for (std::size_t v = 0; v < set.volumes.size(); ++v)
            total += gpuVolumeBytes(set, v);
        for (size_t i = 0; double(total) > budget && i < steps.size(); ++i) {
            keep[size_t(steps[i].volume)] = false;
            if (double(steps[i].keptBytes) <= budget) break;
        }
        if (std::find(keep.begin(), keep.end(), true) == keep.end()) {
            std::size_t smallest = total;
            for (size_t v = 0; v < n; ++v)
                if (parents[v] < 0) smallest = std::min(smallest, gpuVolumeBytes(set, size_t(v)));
            throw Error(form + ": keeps no volume (the smallest root alone needs " +
                        mib(double(smallest)) + " MiB)");
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

} // namespace pb::profile
