#pragma once
// What omitting each probe volume costs, measured by `probebench volumes --rank`
// (costmodel/VolumeRanking.h) and stored next to the probe file (VolumeRanksFile.h), so that
// gi.volume_lod=rank_budget_mib:MIB can drop the volumes of least value per byte at render
// time without the scene or its views. Plain data, GL-free.
#include <cstdint>
#include <string>
#include <vector>

namespace pb::probes {

// Omitting a volume omits the volumes nested in it (profile/GiVolumeLod.h), so every figure
// is of the volume together with its descendants ("subtree").
struct VolumeRank {
    std::string name;
    // Accuracy lost: relative MSE of the indirect irradiance (E x fade + (1 - fade) x ambient,
    // what the lighting applies) over every pixel of the ranking's views, the subtree omitted
    // against everything kept: sum |E' - E|^2 / sum |E|^2 (as metrics::relativeMse).
    double loss = 0;
    std::uint64_t bytes = 0;       // GPU bytes of the subtree, one scenario resident
    std::int64_t pixels = 0;       // pixels of the views the subtree shades (smallest volume rule)
    int views = 0;                 // views in which it shades at least one pixel
    std::int64_t lookups = 0;      // DDGI lookups of the subtree's draws, gi.multi_volume=naive
    std::int64_t lookupsSaved = 0; // lookups gone with the subtree under gi.multi_volume=stencil
                                   // (its pixels that no other volume takes over)
    // Loss per MiB: what rank_budget_mib keeps the most of.
    double valuePerMiB() const { return bytes ? loss / (double(bytes) / (1024.0 * 1024.0)) : 0; }
};

struct VolumeRanks {
    std::uint64_t inputHash = 0;     // ProbeSet::inputHash of the ranked set
    std::string scenario;            // the lighting scenario the errors were measured in
    std::string views;               // "worst-case", "all" or the view names, as given
    int width = 0, height = 0;       // per view
    std::vector<VolumeRank> volumes; // in the probe file's order
    const VolumeRank* find(const std::string& name) const {
        for (const VolumeRank& r : volumes)
            if (r.name == name) return &r;
        return nullptr;
    }
};

} // namespace pb::probes
