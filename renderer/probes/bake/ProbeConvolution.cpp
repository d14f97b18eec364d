#include "probes/bake/ProbeConvolution.h"

#include "core/FloatLanes.h"
#include "core/Luminance.h"
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"

#include <cmath>
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

void ProbeConvolution::irradiance(const float* rgbx, float* out) const {
    // Lane c computes sum_c += w * L_c exactly like a scalar loop (FloatLanes.h).
    for (size_t t = 0; t + 1 < irr_.start.size(); ++t) {
        Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int e = irr_.start[t]; e < irr_.start[t + 1]; ++e)
            sum += irr_.weight[size_t(e)] * load4(rgbx + 4 * size_t(irr_.ray[size_t(e)]));
        out[3 * t] = sum[0];
        out[3 * t + 1] = sum[1];
        out[3 * t + 2] = sum[2];
    }
}

void ProbeConvolution::irradianceLumaVariance(const float* rgbx, float* out) const {
    // Each ray's luminance once (every texel's two sums read it again; the same values).
    thread_local std::vector<float> rayLuma;
    rayLuma.resize(std::size_t(rays_));
    for (int r = 0; r < rays_; ++r)
        rayLuma[std::size_t(r)] = luminance(rgbx + 4 * size_t(r));
    auto luma = [&](int r) { return rayLuma[std::size_t(r)]; };
    for (size_t t = 0; t + 1 < irr_.start.size(); ++t) {
        float e = 0.0f;
        for (int k = irr_.start[t]; k < irr_.start[t + 1]; ++k)
            e += irr_.weight[size_t(k)] * luma(irr_.ray[size_t(k)]);
        const float mu = e / float(M_PI);
        float v = 0.0f;
        for (int k = irr_.start[t]; k < irr_.start[t + 1]; ++k) {
            const float w = irr_.weight[size_t(k)], dy = luma(irr_.ray[size_t(k)]) - mu;
            v += w * w * dy * dy;
        }
        out[t] = v;
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
