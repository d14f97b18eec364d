#include "probes/AbsentProbeFill.h"

#include <cstdint>
#include <limits>
#include <queue>
#include <tuple>

namespace pb::probes {

bool fillable(const ProbeState& s, float backfaceThreshold) {
    // The geometry pass's own test (GeometryPass.cpp): valid = !(ratio > threshold).
    return !s.stored && !s.irradianceOnly && !(s.backfaceRatio > backfaceThreshold);
}

std::vector<int> fillSources(const ProbeVolume& v, const std::vector<ProbeState>& states,
                             float backfaceThreshold) {
    const std::size_t n = states.size();
    bool any = false;
    for (const ProbeState& s : states)
        any = any || fillable(s, backfaceThreshold);
    if (!any || n != std::size_t(v.probeCount())) return {};

    // Nearest stored probe of every grid point: Dijkstra over the 26-neighbour grid, each
    // point carrying the seed it was reached from and keyed by its true distance to that seed
    // (the usual propagated Voronoi; exact on a grid but for rare ties between far seeds).
    // Deterministic: the queue orders by (distance, seed, probe).
    const glm::vec3 cell = v.cellSize();
    auto grid = [&](int i) { return glm::vec3(v.probeCoords(i)) * cell; };
    std::vector<int> seed(n, -1);
    std::vector<float> best(n, std::numeric_limits<float>::infinity());
    using Item = std::tuple<float, int, int>; // squared distance, seed, probe
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (std::size_t i = 0; i < n; ++i)
        if (states[i].stored && states[i].valid) {
            best[i] = 0.0f;
            seed[i] = int(i);
            queue.emplace(0.0f, int(i), int(i));
        }
    std::vector<std::uint8_t> done(n, 0);
    while (!queue.empty()) {
        const auto [d2, s, p] = queue.top();
        queue.pop();
        if (done[std::size_t(p)] || seed[std::size_t(p)] != s) continue;
        done[std::size_t(p)] = 1;
        const glm::ivec3 c = v.probeCoords(p);
        const glm::vec3 origin = grid(s);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(q, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(q, v.counts)))
                        continue;
                    const int qi = v.probeIndex(q);
                    if (done[std::size_t(qi)]) continue;
                    const glm::vec3 d = grid(qi) - origin;
                    const float e2 = glm::dot(d, d);
                    const int old = seed[std::size_t(qi)];
                    if (e2 < best[std::size_t(qi)] || (e2 == best[std::size_t(qi)] && s < old)) {
                        best[std::size_t(qi)] = e2;
                        seed[std::size_t(qi)] = s;
                        queue.emplace(e2, s, qi);
                    }
                }
    }
    std::vector<int> sources(n);
    for (std::size_t i = 0; i < n; ++i)
        sources[i] = fillable(states[i], backfaceThreshold) ? seed[i] : int(i);
    return sources;
}

std::vector<ProbeState> lookupStates(const ProbeVolume& v, const std::vector<ProbeState>& states,
                                     const std::vector<int>& sources) {
    std::vector<ProbeState> out = states;
    if (sources.size() != states.size()) return out;
    const glm::vec3 cell = v.cellSize();
    for (std::size_t i = 0; i < states.size(); ++i) {
        const int s = sources[i];
        if (s < 0 || std::size_t(s) == i) continue;
        // Grid points differ by whole cells per axis (count-1 axes: both at the centre).
        const glm::vec3 step = glm::vec3(v.probeCoords(s) - v.probeCoords(int(i))) * cell;
        out[i].offset = step + states[std::size_t(s)].offset;
        out[i].valid = true;
    }
    return out;
}

} // namespace pb::probes
