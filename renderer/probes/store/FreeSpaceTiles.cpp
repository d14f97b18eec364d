#include "probes/store/FreeSpaceTiles.h"

#include "core/Error.h"
#include "core/Luminance.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeLayout.h"
#include "probes/ProbeSampler.h"
#include "probes/store/MemoryReport.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace pb::probes {
namespace {

constexpr glm::vec3 kLocalAxes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                     {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

// What a lookup reads when it reads only this probe's irradiance from this direction.
float tileLuminance(const ProbeTexture& t, const glm::ivec3& c, const glm::vec3& localDir) {
    const glm::vec2 tc = tileCoord(c, localDir, kIrradianceInterior);
    float e[4] = {0, 0, 0, 0};
    bilinearFetch(t, tc.x, tc.y, c.y, e);
    return luminance(e);
}

// A tenth of the stored probes' mean luminance in one scenario (the floor of step 1).
float luminanceFloor(const ProbeSet& set, std::size_t scenario,
                     const std::vector<std::vector<std::uint8_t>>& keep) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t v = 0; v < set.volumes.size(); ++v)
        for (int p = 0; p < set.volumes[v].probeCount(); ++p) {
            if (!keep[v][std::size_t(p)] || !set.states[v][std::size_t(p)].valid) continue;
            const glm::ivec3 c = set.volumes[v].probeCoords(p);
            for (const glm::vec3& d : kLocalAxes)
                sum += tileLuminance(set.irradiance[scenario][v], c, d);
            n += 6;
        }
    return n ? float(0.1 * sum / double(n)) : 0.0f;
}

void checkShapes(const ProbeSet& set, const std::vector<std::vector<std::uint8_t>>& keep) {
    if (keep.size() != set.volumes.size()) throw Error("free-space tiles: one mask per volume");
    for (std::size_t v = 0; v < keep.size(); ++v)
        if (keep[v].size() != set.states[v].size())
            throw Error("free-space tiles: one flag per probe");
}

} // namespace

double defaultFreeSpaceBudget(double storedBytes) {
    return storedBytes / (1.0 - kFreeSpaceTileShare);
}

std::vector<std::vector<float>> standInErrors(const ProbeSet& traced,
                                              const std::vector<std::vector<std::uint8_t>>& keep) {
    checkShapes(traced, keep);
    std::vector<float> floors;
    for (std::size_t s = 0; s < traced.irradiance.size(); ++s)
        floors.push_back(luminanceFloor(traced, s, keep));
    std::vector<std::vector<float>> out;
    for (std::size_t v = 0; v < traced.volumes.size(); ++v) {
        const ProbeVolume& vol = traced.volumes[v];
        // The states as sparse storage without tiles leaves them: the stand-ins' sources.
        std::vector<ProbeState> stored = traced.states[v];
        for (std::size_t p = 0; p < stored.size(); ++p) {
            stored[p].stored = stored[p].valid && keep[v][p];
            stored[p].irradianceOnly = false;
            stored[p].valid = stored[p].stored;
        }
        const std::vector<int> src = fillSources(vol, stored, traced.settings.backfaceThreshold);
        std::vector<float> err(stored.size(), 0.0f);
        for (std::size_t p = 0; p < stored.size(); ++p) {
            if (keep[v][p] || !traced.states[v][p].valid) continue;
            const int from = src.empty() ? -1 : src[p];
            // No stand-in (none stored in the volume, or read as inside geometry): a lookup
            // loses this corner whatever its light is.
            if (from < 0 || from == int(p)) {
                err[p] = std::numeric_limits<float>::infinity();
                continue;
            }
            const glm::ivec3 own = vol.probeCoords(int(p)), in = vol.probeCoords(from);
            for (std::size_t s = 0; s < traced.irradiance.size(); ++s) {
                const ProbeTexture& t = traced.irradiance[s][v];
                for (const glm::vec3& d : kLocalAxes) {
                    const float e = tileLuminance(t, own, d);
                    const float diff = std::abs(tileLuminance(t, in, d) - e);
                    const float rel = diff / std::max(e, floors[s]);
                    err[p] = std::max(err[p], rel > 0.0f ? rel : 0.0f);
                }
            }
        }
        out.push_back(std::move(err));
    }
    return out;
}

FreeSpaceTileChoice chooseFreeSpaceTiles(const ProbeSet& traced,
                                         const std::vector<std::vector<std::uint8_t>>& keep,
                                         double budgetBytes) {
    const std::vector<std::vector<float>> errors = standInErrors(traced, keep); // checks shapes
    FreeSpaceTileChoice c;
    std::vector<std::size_t> stored;
    std::vector<std::tuple<float, std::size_t, std::size_t>> ranked; // score, volume, probe
    for (std::size_t v = 0; v < traced.volumes.size(); ++v) {
        c.tiles.emplace_back(traced.states[v].size(), 0);
        std::size_t n = 0;
        for (std::size_t p = 0; p < traced.states[v].size(); ++p) {
            if (!traced.states[v][p].valid) continue;
            if (keep[v][p])
                ++n;
            else
                ranked.emplace_back(errors[v][p], v, p);
        }
        stored.push_back(n);
    }
    c.candidates = ranked.size();
    // Highest score first; ties by volume, then probe.
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
        return std::make_tuple(-std::get<0>(a), std::get<1>(a), std::get<2>(a)) <
               std::make_tuple(-std::get<0>(b), std::get<1>(b), std::get<2>(b));
    });
    // The set's bytes with the first k ranked probes as tiles. The packed textures grow in
    // steps, so the search below keeps only k it has checked against the budget.
    auto bytesWith = [&](std::size_t k) {
        std::vector<std::size_t> tiles(traced.volumes.size(), 0);
        for (std::size_t i = 0; i < k; ++i)
            ++tiles[std::get<1>(ranked[i])];
        return double(memoryReport(traced.volumes, traced.format(), &stored, &tiles)
                          .total.storedTotal());
    };
    const double budget = budgetBytes > 0.0 ? budgetBytes : defaultFreeSpaceBudget(bytesWith(0));
    std::size_t lo = 0, hi = ranked.size(); // the largest k within the budget
    if (bytesWith(0) > budget) hi = 0;
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo + 1) / 2;
        if (bytesWith(mid) <= budget)
            lo = mid;
        else
            hi = mid - 1;
    }
    c.chosen = lo;
    for (std::size_t i = 0; i < c.chosen; ++i)
        c.tiles[std::get<1>(ranked[i])][std::get<2>(ranked[i])] = 1;
    c.worstLeft = c.chosen < ranked.size() ? std::get<0>(ranked[c.chosen]) : 0.0f;
    return c;
}

} // namespace pb::probes
