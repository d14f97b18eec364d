// Principal-axis work of the BC6H encoder: endpoint lines through each subset and the cheap
// ranking of two-region partitions. See Bc6hFit.h.
#include "probes/bc6h/Bc6hFit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pb::probes::bc6h {
namespace {

// Largest eigenvalue of a symmetric positive semi-definite 3x3 matrix: Newton's method on
// the characteristic polynomial started at the trace, which lies above it; the polynomial is
// convex there, so the iteration descends monotonically onto the largest root. In double: the
// coefficients cancel badly in float for blocks of bright, nearly flat texels.
double largestEigenvalue(const float cov[3][3]) {
    const double a = cov[0][0], b = cov[0][1], c = cov[0][2];
    const double d = cov[1][1], e = cov[1][2], f = cov[2][2];
    const double trace = a + d + f;
    const double minors = (a * d - b * b) + (a * f - c * c) + (d * f - e * e);
    const double det = a * (d * f - e * e) - b * (b * f - c * e) + c * (b * e - c * d);
    double lambda = trace;
    for (int it = 0; it < 8; ++it) {
        const double p = ((lambda - trace) * lambda + minors) * lambda - det;
        const double dp = (3.0 * lambda - 2.0 * trace) * lambda + minors;
        if (!(dp > 0.0)) break;
        const double step = p / dp;
        lambda -= step;
        if (!(step > 1e-4 * trace)) break;
    }
    return std::max(lambda, 0.0);
}

// Principal axis (unit length) and the variance along it. The eigenvector of the largest
// eigenvalue is the cross product of two rows of (C - lambda I); the longest of the three
// products is the best conditioned. When lambda is (nearly) repeated any direction in its
// plane fits equally well, so the dominant column of C serves.
float principalAxis(const float cov[3][3], float axis[3]) {
    const double lambda = largestEigenvalue(cov);
    double r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r[i][j] = cov[i][j] - (i == j ? lambda : 0.0);
    double best[3] = {0, 0, 0}, bestLen = 0.0;
    for (int p = 0; p < 3; ++p) {
        const double* u = r[p];
        const double* v = r[(p + 1) % 3];
        const double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        const double len = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        if (len > bestLen) {
            bestLen = len;
            for (int i = 0; i < 3; ++i)
                best[i] = x[i];
        }
    }
    const double trace = cov[0][0] + cov[1][1] + cov[2][2];
    if (!(bestLen > 1e-10 * trace * trace * trace * trace)) {
        int k = 0;
        if (cov[1][1] > cov[k][k]) k = 1;
        if (cov[2][2] > cov[k][k]) k = 2;
        for (int i = 0; i < 3; ++i)
            best[i] = cov[i][k];
        bestLen = best[0] * best[0] + best[1] * best[1] + best[2] * best[2];
        if (!(bestLen > 0.0)) {
            // Constant subset: any axis works, the endpoints collapse to the mean.
            axis[0] = axis[1] = axis[2] = 0.57735027f;
            return 0.0f;
        }
    }
    const double inv = 1.0 / std::sqrt(bestLen);
    for (int i = 0; i < 3; ++i)
        axis[i] = static_cast<float>(best[i] * inv);
    return static_cast<float>(lambda);
}

struct SubsetStats {
    float count = 0;
    float mean[3] = {};
    float cov[3][3] = {};
};

SubsetStats gatherStats(const BlockTarget& t, std::uint16_t mask) {
    SubsetStats s;
    for (int i = 0; i < 16; ++i) {
        if (!((mask >> i) & 1)) continue;
        s.count += 1;
        for (int c = 0; c < 3; ++c)
            s.mean[c] += t.q[i][c];
    }
    if (s.count == 0) return s;
    for (int c = 0; c < 3; ++c)
        s.mean[c] /= s.count;
    for (int i = 0; i < 16; ++i) {
        if (!((mask >> i) & 1)) continue;
        float d[3];
        for (int c = 0; c < 3; ++c)
            d[c] = t.q[i][c] - s.mean[c];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                s.cov[a][b] += d[a] * d[b];
    }
    return s;
}

} // namespace

void fitSubset(const BlockTarget& t, std::uint16_t mask, int anchor, int subset, Lines& out) {
    const SubsetStats s = gatherStats(t, mask);
    float axis[3];
    principalAxis(s.cov, axis);
    float lo = 0.0f, hi = 0.0f, anchorT = 0.0f;
    bool first = true;
    for (int i = 0; i < 16; ++i) {
        if (!((mask >> i) & 1)) continue;
        float p = 0.0f;
        for (int c = 0; c < 3; ++c)
            p += (t.q[i][c] - s.mean[c]) * axis[c];
        lo = first ? p : std::min(lo, p);
        hi = first ? p : std::max(hi, p);
        first = false;
        if (i == anchor) anchorT = p;
    }
    if (anchorT - lo > hi - anchorT) std::swap(lo, hi);
    for (int c = 0; c < 3; ++c) {
        out.e[2 * subset][c] = std::clamp(s.mean[c] + lo * axis[c], 0.0f, kMaxInterp);
        out.e[2 * subset + 1][c] = std::clamp(s.mean[c] + hi * axis[c], 0.0f, kMaxInterp);
    }
}

PartitionEstimator::PartitionEstimator(const BlockTarget& t) {
    // Centred on the block mean so the float sums below do not cancel catastrophically.
    float mean[3] = {};
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 3; ++c)
            mean[c] += t.q[i][c] / 16.0f;
    for (int i = 0; i < 16; ++i) {
        float d[3];
        for (int c = 0; c < 3; ++c)
            d[c] = t.q[i][c] - mean[c];
        const float moments[9] = {d[0],        d[1],        d[2],        d[0] * d[0], d[0] * d[1],
                                  d[0] * d[2], d[1] * d[1], d[1] * d[2], d[2] * d[2]};
        for (int k = 0; k < 9; ++k) {
            texel_[k][i] = moments[k];
            total_[k] += moments[k];
        }
    }
}

void PartitionEstimator::scores(float limit, float out[32]) const {
    // Subset 1 as a 0/1 weight per texel: branch-free sums the compiler vectorises.
    static const auto weights = [] {
        std::array<std::array<float, 16>, 32> w{};
        for (int p = 0; p < 32; ++p)
            for (int i = 0; i < 16; ++i)
                w[p][i] = static_cast<float>((kPartitions[p] >> i) & 1);
        return w;
    }();
    constexpr float toHalfBits2 = (31.0f / 64.0f) * (31.0f / 64.0f);
    // Moment order: 3 means, then xx xy xz yy yz zz; the diagonal ones first serve the bound.
    constexpr int kBoundMoments[6] = {0, 1, 2, 3, 6, 8};
    constexpr int kCrossMoments[3] = {4, 5, 7};
    for (int p = 0; p < 32; ++p) {
        const float* w = weights[p].data();
        float sums[2][9] = {};
        auto sumMoment = [&](int k) {
            // Four explicit lanes: the vectoriser may not reorder a plain float sum.
            float lane[4] = {};
            for (int i = 0; i < 16; i += 4)
                for (int l = 0; l < 4; ++l)
                    lane[l] += w[i + l] * texel_[k][i + l];
            const float sum = (lane[0] + lane[1]) + (lane[2] + lane[3]);
            sums[1][k] = sum;
            sums[0][k] = total_[k] - sum;
        };
        for (int k : kBoundMoments)
            sumMoment(k);
        const float n1 = static_cast<float>(__builtin_popcount(kPartitions[p]));
        const float n[2] = {16.0f - n1, n1};
        float trace[2];
        for (int s = 0; s < 2; ++s) {
            const float* m = sums[s];
            trace[s] = m[3] + m[6] + m[8] - (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) / n[s];
        }
        // trace - lambda + lambda / 49 >= trace / 49, since lambda <= trace.
        if ((trace[0] + trace[1]) / 49.0f * toHalfBits2 >= limit) {
            out[p] = std::numeric_limits<float>::infinity();
            continue;
        }
        for (int k : kCrossMoments)
            sumMoment(k);
        float result = 0.0f;
        for (int s = 0; s < 2; ++s) {
            const float* m = sums[s];
            const float mu[3] = {m[0] / n[s], m[1] / n[s], m[2] / n[s]};
            float cov[3][3];
            cov[0][0] = m[3] - n[s] * mu[0] * mu[0];
            cov[0][1] = cov[1][0] = m[4] - n[s] * mu[0] * mu[1];
            cov[0][2] = cov[2][0] = m[5] - n[s] * mu[0] * mu[2];
            cov[1][1] = m[6] - n[s] * mu[1] * mu[1];
            cov[1][2] = cov[2][1] = m[7] - n[s] * mu[1] * mu[2];
            cov[2][2] = m[8] - n[s] * mu[2] * mu[2];
            const float along = static_cast<float>(largestEigenvalue(cov));
            const float total = cov[0][0] + cov[1][1] + cov[2][2];
            // Residual off the axis plus 8 evenly spaced levels over a spread of
            // ~sqrt(12 var): step^2 / 12 ~ var / 49.
            result += std::max(total - along, 0.0f) + along / 49.0f;
        }
        out[p] = result * toHalfBits2;
    }
}

} // namespace pb::probes::bc6h
