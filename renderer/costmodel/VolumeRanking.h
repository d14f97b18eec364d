#pragma once
// The value of each probe volume: what the frame loses when the volume (and, by the
// gi.volume_lod rule, every volume nested in it) is omitted, against what it costs in GPU
// memory and GI lookups. `probebench volumes --rank` prints it; `--write-ranks` stores it next
// to the probe file for gi.volume_lod=rank_budget_mib (probes/store/VolumeRanksFile.h).
//
// GL-free and deterministic: the views' surfaces come from the CPU primary rays of
// views::CoverageTester (the GBuffer's hit point and face normal), the irradiance from the CPU
// reference sampler (probes::ProbeSampler, which the GI pass reproduces to 1e-3). Per surface
// pixel the indirect irradiance the lighting applies is E x fade + (1 - fade) x ambient (the
// hemispherical ambient outside every volume). Omitting a subtree changes only the pixels
// whose shading volume (the smallest whose influence holds the point) lies in it: they go to
// the smallest remaining volume holding the point, or to the ambient. The loss is the relative
// MSE of that irradiance over every surface pixel of every view, sum |E' - E|^2 / sum |E|^2
// (metrics::relativeMse's definition), so losses of different volumes add up on one scale.
// GI time is given as lookup counts (hardware-independent), not measured pass times.
#include "probes/ProbeSet.h"
#include "probes/VolumeRank.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::costmodel {

struct RankingInputs {
    const scene::Scene* scene = nullptr;
    const probes::ProbeSet* probes = nullptr;
    int scenario = 0;
    std::vector<scene::View> views; // the pixels that count
    std::string viewsLabel;         // recorded in the result ("worst-case", "all", names)
    int width = 320, height = 180;  // per view
    // The lighting's fallback outside every volume (render::defaultFrameSettings).
    glm::vec3 ambientUp{0.0f}, ambientDown{0.0f};
};

// One VolumeRank per volume of the set, in file order. Throws pb::Error for a bad scenario.
probes::VolumeRanks rankVolumes(const RankingInputs& in);

// Indices into r.volumes by loss, the largest first (ties: file order): the listing order.
std::vector<int> byLoss(const probes::VolumeRanks& r);

} // namespace pb::costmodel
