#include "costmodel/VolumeRanking.h"

#include "core/Error.h"
#include "profile/GiVolumeLod.h"
#include "core/ParallelFor.h"
#include "probes/ProbeSampler.h"
#include "views/WorstCaseView.h"

#include <algorithm>
#include <numeric>

namespace pb::costmodel {

namespace {

// Per image row, so rows can run in parallel and still sum in one fixed order.
struct RowSums {
    double reference = 0;
    std::vector<double> error;         // [volume]
    std::vector<std::int64_t> shaded;  // [volume]: pixels its subtree shades
    std::vector<std::int64_t> naive;   // [volume]: pixels in its own influence
    std::vector<std::int64_t> orphans; // [volume]: shaded pixels no other volume takes
};

glm::vec3 ambient(const RankingInputs& in, const glm::vec3& n) {
    return glm::mix(in.ambientDown, in.ambientUp, n.y * 0.5f + 0.5f);
}

glm::vec3 lit(const probes::IrradianceSample& s, const glm::vec3& amb) {
    return s.irradiance + (1.0f - s.weight) * amb;
}

float squared(const glm::vec3& d) {
    return glm::dot(d, d);
}

} // namespace

probes::VolumeRanks rankVolumes(const RankingInputs& in) {
    const probes::ProbeSet& set = *in.probes;
    if (in.scenario < 0 || size_t(in.scenario) >= set.scenarios.size())
        throw Error("probe set has no scenario #" + std::to_string(in.scenario));
    const std::vector<int> parents = probes::validateVolumes(set.volumes, "probe set");
    const size_t n = set.volumes.size();
    // inSubtree[v][u]: u is v or nested (at any depth) in v.
    std::vector<std::vector<bool>> inSubtree(n, std::vector<bool>(n, false));
    for (size_t u = 0; u < n; ++u)
        for (int a = int(u); a >= 0; a = parents[size_t(a)])
            inSubtree[size_t(a)][u] = true;
    std::vector<float> box(n);
    for (size_t v = 0; v < n; ++v)
        box[v] = set.volumes[v].boxVolume();

    const views::CoverageTester tester(*in.scene, set);
    const probes::ProbeSampler sampler(set, in.scenario);
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x)
            pixels.push_back({x, y});

    double reference = 0;
    std::vector<double> error(n, 0.0);
    std::vector<std::int64_t> shaded(n, 0), naive(n, 0), orphans(n, 0);
    std::vector<int> viewsSeen(n, 0);
    for (const scene::View& view : in.views) {
        const std::vector<views::SurfacePoint> points =
            tester.surfacePoints(view, in.width, in.height, pixels);
        std::vector<RowSums> rows(size_t(in.height));
        pb::parallelFor(size_t(in.height), 0, [&](size_t row, int) {
            RowSums& r = rows[row];
            r.error.assign(n, 0.0);
            r.shaded.assign(n, 0);
            r.naive.assign(n, 0);
            r.orphans.assign(n, 0);
            std::vector<bool> influences(n);
            for (int x = 0; x < in.width; ++x) {
                const views::SurfacePoint& p = points[row * size_t(in.width) + size_t(x)];
                if (!p.hit) continue;
                const glm::vec3 eyeDir = glm::normalize(view.position - p.position);
                const glm::vec3 amb = ambient(in, p.normal);
                const int chosen = sampler.selectVolume(p.position);
                const glm::vec3 e =
                    chosen < 0
                        ? amb
                        : lit(sampler.sampleVolume(chosen, p.position, p.normal, eyeDir), amb);
                r.reference += squared(e);
                if (chosen < 0) continue;
                for (size_t u = 0; u < n; ++u) {
                    influences[u] = sampler.influencesPoint(int(u), p.position);
                    r.naive[u] += influences[u];
                }
                for (size_t v = 0; v < n; ++v) {
                    if (!inSubtree[v][size_t(chosen)]) continue;
                    ++r.shaded[v];
                    // The sampler's rule among the rest: smallest box, ties the first in file.
                    int next = -1;
                    for (size_t u = 0; u < n; ++u)
                        if (influences[u] && !inSubtree[v][u] &&
                            (next < 0 || box[u] < box[size_t(next)]))
                            next = int(u);
                    glm::vec3 without = amb;
                    if (next >= 0)
                        without =
                            lit(sampler.sampleVolume(next, p.position, p.normal, eyeDir), amb);
                    else
                        ++r.orphans[v];
                    r.error[v] += squared(without - e);
                }
            }
        });
        std::vector<std::int64_t> shadedHere(n, 0);
        for (const RowSums& r : rows) {
            reference += r.reference;
            for (size_t v = 0; v < n; ++v) {
                error[v] += r.error[v];
                shadedHere[v] += r.shaded[v];
                naive[v] += r.naive[v];
                orphans[v] += r.orphans[v];
            }
        }
        for (size_t v = 0; v < n; ++v) {
            shaded[v] += shadedHere[v];
            viewsSeen[v] += shadedHere[v] > 0;
        }
    }

    probes::VolumeRanks out;
    out.inputHash = set.inputHash;
    out.scenario = set.scenarios[size_t(in.scenario)].name;
    out.views = in.viewsLabel;
    out.width = in.width;
    out.height = in.height;
    for (size_t v = 0; v < n; ++v) {
        probes::VolumeRank r;
        r.name = set.volumes[v].name;
        // A black reference (no light at all) keeps the loss finite for the ranks file.
        r.loss = error[v] / std::max(reference, 1e-30);
        for (size_t u = 0; u < n; ++u)
            if (inSubtree[v][u]) {
                r.bytes += profile::gpuVolumeBytes(set, size_t(u));
                r.lookups += naive[u];
            }
        r.pixels = shaded[v];
        r.views = viewsSeen[v];
        r.lookupsSaved = orphans[v];
        out.volumes.push_back(std::move(r));
    }
    return out;
}

std::vector<int> byLoss(const probes::VolumeRanks& r) {
    std::vector<int> order(r.volumes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return r.volumes[size_t(a)].loss > r.volumes[size_t(b)].loss;
    });
    return order;
}

} // namespace pb::costmodel
