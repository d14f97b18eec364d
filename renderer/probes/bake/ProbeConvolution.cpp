#include "probes/bake/ProbeConvolution.h"

#include "core/FloatLanes.h"
#include "core/Luminance.h"
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <stdexcept>

namespace pb::probes {
namespace {
float powVisibility(float c) {
    static_assert(kVisibilityPower == 50, "update the squaring chain");
    float c2 = c * c, c4 = c2 * c2, c8 = c4 * c4, c16 = c8 * c8, c32 = c16 * c16;
    return c32 * c16 * c2;
}
} // namespace

void ProbeConvolution::build(const std::vector<glm::vec3>& dirs, int interior, float scale,
                             bool power, Sparse& out) {
    const int n = int(dirs.size());
    std::vector<float> row(static_cast<size_t>(n));
    out.start.assign(1, 0);
    for (int j = 0; j < interior; ++j)
        for (int i = 0; i < interior; ++i) {
            glm::vec3 nt = octTexelDirection(i, j, interior);
            double sum = 0.0;
            int nearest = 0;
            float best = -2.0f;
            for (int r = 0; r < n; ++r) {
                float c = glm::dot(nt, dirs[size_t(r)]);
                if (c > best) best = c, nearest = r;
                row[size_t(r)] = c > 0.0f ? (power ? powVisibility(c) : c) : 0.0f;
                sum += row[size_t(r)];
            }
            if (sum > 0.0) {
                // Drop negligible weights, then renormalise what is kept to sum exactly.
                double kept = 0.0;
                for (int r = 0; r < n; ++r)
                    if (row[size_t(r)] > kWeightPrune * sum) kept += row[size_t(r)];
                for (int r = 0; r < n; ++r)
                    if (row[size_t(r)] > kWeightPrune * sum) {
                        out.ray.push_back(r);
                        out.weight.push_back(float(double(row[size_t(r)]) * scale / kept));
                    }
            } else if (n > 0) {
                out.ray.push_back(nearest);
                out.weight.push_back(scale);
            }
            out.start.push_back(int(out.ray.size()));
        }
}

ProbeConvolution::ProbeConvolution(const std::vector<glm::vec3>& dirs, Parts parts)
    : rays_(int(dirs.size())), parts_(parts) {
    build(dirs, kIrradianceInterior, float(M_PI), false, irr_);
    if (parts == Parts::WithVisibility) build(dirs, kVisibilityInterior, 1.0f, true, vis_);
    shBasis_.resize(dirs.size() * kShL2Coefficients);
    for (std::size_t r = 0; r < dirs.size(); ++r)
        shBasis(dirs[r], &shBasis_[r * kShL2Coefficients]);
}

namespace {

// A texel's sum is one chain of dependent additions (its order fixes the rounding), so one
// texel at a time waits on the adder's latency at every weight. kChains texels run side by side
// instead: their first min(lengths) weights interleaved, then each one's remaining weights.
// Every texel still adds its own weights in their own order: the same bits.
constexpr std::size_t kChains = 4;

// The kChains texels from t0 (compressed rows `start`): each one's weights [at, end), and how
// many weights all of them have (`common`). Past the last texel a chain repeats the first:
// `chains` says how many are real, and only their sums are written.
struct ChainGroup {
    std::size_t chains;
    int at[kChains], end[kChains], common;
};
ChainGroup chainGroup(const std::vector<int>& start, std::size_t t0) {
    const std::size_t texels = start.size() - 1;
    ChainGroup g{std::min(kChains, texels - t0), {}, {}, std::numeric_limits<int>::max()};
    for (std::size_t c = 0; c < kChains; ++c) {
        const std::size_t t = t0 + (c < g.chains ? c : 0);
        g.at[c] = start[t];
        g.end[c] = start[t + 1];
        g.common = std::min(g.common, g.end[c] - g.at[c]);
    }
    return g;
}

} // namespace

void ProbeConvolution::irradiance(const float* rgbx, float* out) const {
    const std::size_t texels = irr_.start.size() - 1;
    const int* ray = irr_.ray.data();
    const float* weight = irr_.weight.data();
    auto term = [&](int e) { return weight[e] * load4(rgbx + 4 * std::size_t(ray[e])); };
    for (std::size_t t0 = 0; t0 < texels; t0 += kChains) {
        const ChainGroup g = chainGroup(irr_.start, t0);
        const std::size_t chains = g.chains;
        const int *at = g.at, *end = g.end, common = g.common;
        Float4 sum[kChains] = {};
        for (int k = 0; k < common; ++k)
            for (std::size_t c = 0; c < kChains; ++c)
                sum[c] += term(at[c] + k);
        for (std::size_t c = 0; c < chains; ++c) {
            for (int e = at[c] + common; e < end[c]; ++e)
                sum[c] += term(e);
            out[3 * (t0 + c)] = sum[c][0];
            out[3 * (t0 + c) + 1] = sum[c][1];
            out[3 * (t0 + c) + 2] = sum[c][2];
        }
    }
}

void ProbeConvolution::irradianceLumaVariance(const float* rgbx, float* out) const {
    // Each ray's luminance once (every texel's two sums read it again; the same values).
    thread_local std::vector<float> rayLuma;
    rayLuma.resize(std::size_t(rays_));
    for (int r = 0; r < rays_; ++r)
        rayLuma[std::size_t(r)] = luminance(rgbx + 4 * size_t(r));
    const int* ray = irr_.ray.data();
    const float* weight = irr_.weight.data();
    const float* luma = rayLuma.data();
    // kChains texels side by side, as irradiance(): per texel the scalar sums in their order.
    const std::size_t texels = irr_.start.size() - 1;
    for (std::size_t t0 = 0; t0 < texels; t0 += kChains) {
        const ChainGroup g = chainGroup(irr_.start, t0);
        const std::size_t chains = g.chains;
        const int *at = g.at, *end = g.end, common = g.common;
        float e[kChains] = {}, v[kChains] = {}, mu[kChains] = {};
        for (int k = 0; k < common; ++k)
            for (std::size_t c = 0; c < kChains; ++c)
                e[c] += weight[at[c] + k] * luma[ray[at[c] + k]];
        for (std::size_t c = 0; c < chains; ++c) {
            for (int k = at[c] + common; k < end[c]; ++k)
                e[c] += weight[k] * luma[ray[k]];
            mu[c] = e[c] / float(M_PI);
        }
        for (std::size_t c = chains; c < kChains; ++c)
            mu[c] = mu[0];
        for (int k = 0; k < common; ++k)
            for (std::size_t c = 0; c < kChains; ++c) {
                const float w = weight[at[c] + k], dy = luma[ray[at[c] + k]] - mu[c];
                v[c] += w * w * dy * dy;
            }
        for (std::size_t c = 0; c < chains; ++c) {
            for (int k = at[c] + common; k < end[c]; ++k) {
                const float w = weight[k], dy = luma[ray[k]] - mu[c];
                v[c] += w * w * dy * dy;
            }
            out[t0 + c] = v[c];
        }
    }
}

void ProbeConvolution::visibility(const float* d, float* out) const {
    if (parts_ != Parts::WithVisibility)
        throw std::logic_error("ProbeConvolution::visibility: built without visibility weights");
    for (size_t t = 0; t + 1 < vis_.start.size(); ++t) {
        float m = 0, m2 = 0;
        for (int e = vis_.start[t]; e < vis_.start[t + 1]; ++e) {
            int k = vis_.ray[size_t(e)];
            float w = vis_.weight[size_t(e)];
            m += w * d[k];
            m2 += w * d[k] * d[k];
        }
        out[2 * t] = m;
        out[2 * t + 1] = m2;
    }
}

} // namespace pb::probes
