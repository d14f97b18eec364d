#include "respond/ProbeUpdate.h"

#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"

#include <algorithm>
#include <limits>
#include <map>

namespace pb::respond {

glm::vec3 probeWorldPosition(const probes::ProbeSet& set, const ProbeRef& p) {
    const probes::ProbeVolume& v = set.volumes[std::size_t(p.volume)];
    const glm::ivec3 c = v.probeCoords(p.probe);
    const glm::vec3 offset = set.states[std::size_t(p.volume)][std::size_t(p.probe)].offset;
    return v.toWorld(v.gridLocal(c) + offset);
}

ProbeUpdater::ProbeUpdater(probes::ProbeSet& set, int scenario, Schedule schedule,
                           const ScheduleParams& params)
    : set_(set), scenario_(scenario), schedule_(schedule), params_(params) {
    for (const auto& v : set.volumes) {
        hastenedIndex_.emplace_back(std::size_t(v.probeCount()), 1);
        samplesTaken_.emplace_back(std::size_t(v.probeCount()), 0);
    }
}

std::size_t ProbeUpdater::mark(const Change& change, float radius, bool effective) {
    if (!effective) return 0;
    std::map<std::pair<int, int>, float> dist; // already marked, by (volume, probe)
    for (const Marked& m : order_)
        dist[{m.ref.volume, m.ref.probe}] = m.distance;
    std::size_t touched = 0;
    for (int v = 0; v < int(set_.volumes.size()); ++v)
        for (int i = 0; i < set_.volumes[std::size_t(v)].probeCount(); ++i) {
            const probes::ProbeState& st = set_.states[std::size_t(v)][std::size_t(i)];
            if (!st.valid || !st.stored) continue;
            float d = 0.0f;
            if (!change.global) {
                d = std::numeric_limits<float>::max();
                const glm::vec3 p = probeWorldPosition(set_, {v, i});
                for (const glm::vec3& c : change.points)
                    d = std::min(d, glm::length(p - c));
                if (!(d <= radius)) continue;
            }
            // A new change restarts the probe's hastened state; the nearer change wins the
            // priority.
            hastenedIndex_[std::size_t(v)][std::size_t(i)] =
                hastenedStart(d, change.global ? 0.0f : radius, params_);
            auto it = dist.find({v, i});
            if (it == dist.end())
                dist[{v, i}] = d;
            else
                it->second = std::min(it->second, d);
            ++touched;
        }
    order_.clear();
    for (const auto& [key, d] : dist)
        order_.push_back({{key.first, key.second}, d});
    std::stable_sort(order_.begin(), order_.end(),
                     [](const Marked& a, const Marked& b) { return a.distance < b.distance; });
    next_ = 0;
    return touched;
}

void ProbeUpdater::updateProbe(const ProbeRef& p, const SampleFn& sample) {
    using namespace probes;
    constexpr int n = kIrradianceInterior * kIrradianceInterior;
    float fresh[3 * n], stored[3 * n];
    int& taken = samplesTaken_[std::size_t(p.volume)][std::size_t(p.probe)];
    sample(p, taken, fresh);
    ++taken;
    ProbeTexture& tex = set_.irradiance[std::size_t(scenario_)][std::size_t(p.volume)];
    const glm::ivec3 c = set_.volumes[std::size_t(p.volume)].probeCoords(p.probe);
    float* tile = tileOrigin(tex, c, kIrradianceTile);
    const int pitch = tex.shape.width * kIrradianceChannels;
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i)
            for (int ch = 0; ch < 3; ++ch)
                stored[3 * (j * kIrradianceInterior + i) + ch] =
                    tile[(j + 1) * pitch + (i + 1) * kIrradianceChannels + ch];
    int& index = hastenedIndex_[std::size_t(p.volume)][std::size_t(p.probe)];
    blendTexels(schedule_, params_, index, fresh, stored, n);
    ++index;
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i)
            for (int ch = 0; ch < 3; ++ch)
                tile[(j + 1) * pitch + (i + 1) * kIrradianceChannels + ch] =
                    stored[3 * (j * kIrradianceInterior + i) + ch];
    fillOctahedralBorder(tile, tex.shape.width, kIrradianceChannels, kIrradianceInterior);
}

std::vector<ProbeRef> ProbeUpdater::step(int budget, const SampleFn& sample) {
    std::vector<ProbeRef> updated;
    if (order_.empty()) return updated;
    const std::size_t count =
        budget <= 0 ? order_.size() : std::min(order_.size(), std::size_t(budget));
    for (std::size_t k = 0; k < count; ++k) {
        const ProbeRef p = order_[next_].ref;
        next_ = (next_ + 1) % order_.size();
        updateProbe(p, sample);
        updated.push_back(p);
    }
    return updated;
}

} // namespace pb::respond
