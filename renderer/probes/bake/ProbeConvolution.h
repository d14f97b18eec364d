#pragma once
// Turns one probe's ray results into its texels, with weights computed once per pass (all
// probes of a pass share the directions, see RayDirections.h).
//
// Irradiance texel t (direction n_t, octahedral texel centre) from rays (d_r, L_r):
//     E_t = pi * sum_r max(0, n_t.d_r) L_r / sum_r max(0, n_t.d_r)
// Normalising by the weight sum (not by N/4) makes a uniform radiance L give exactly pi*L
// for any ray count: E is irradiance in the scene's linear units.
// Visibility texel t, with w = max(0, n_t.d_r)^kVisibilityPower and distances already
// clamped and divided by the volume's maxDistance (misses count as 1):
//     mean = sum w d / sum w,   meanSq = sum w d^2 / sum w
// A texel whose weights are all zero (only possible with very few rays) takes the ray
// nearest to its direction. Weights are kept sparse: zeros and normalised weights below
// kWeightPrune are dropped (relative effect < rays * 1e-7, far below half-float precision).
// The rays' SH L2 basis values Y_k(d_r) are kept too (shBasisOfRay): projecting a probe's
// radiance onto SH (RadianceSlab::projectSh) needs them for every probe of the pass.
#include "probes/sh/ShIrradiance.h"

#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

constexpr int kVisibilityPower = 50;
constexpr float kWeightPrune = 1e-7f;

class ProbeConvolution {
public:
    // The radiance passes never convolve visibility: IrradianceOnly skips its weights (196
    // texels x the rays, each a 50th power), and visibility() must not be called then.
    enum class Parts { IrradianceOnly, WithVisibility };
    explicit ProbeConvolution(const std::vector<glm::vec3>& localDirs,
                              Parts parts = Parts::WithVisibility);
    int rays() const { return rays_; }
    // Y_0 .. Y_8 of ray r's direction (probes/sh/ShIrradiance.h shBasis).
    const float* shBasisOfRay(int r) const { return &shBasis_[std::size_t(r) * kShL2Coefficients]; }
    // radiance: rays() x (R, G, B, unused) floats; out: interior texels, row-major, RGB per
    // texel. (Four floats per ray: one SIMD multiply-add per weight, the same per-channel
    // arithmetic in the same order as three scalar sums.)
    void irradiance(const float* rgbx, float* outRgb) const;
    // The variance of each interior texel's luminance estimate, from the rays' sample
    // variance: E_t = sum_e W_e L_e (W: the weights above, pi included), so with mu_t = E_t / pi
    //     var_t = sum_e W_e^2 (Y(L_e) - Y(mu_t))^2
    // (independent samples; the Fibonacci rays are stratified, so this is an upper estimate).
    void irradianceLumaVariance(const float* rgbx, float* outVar) const;
    // dist01: rays() normalised distances; out: interior texels, (mean, meanSq) per texel.
    void visibility(const float* dist01, float* outMeanMeanSq) const;
    // Irradiance texel t's weights (pi included) and their rays, in the order its sum adds
    // them: E_t = sum_k weight[k] L(ray[k]), k = 0 .. count-1, left to right. That order is the
    // contract irradiance() and irradianceLumaVariance() keep, whatever they interleave.
    struct WeightRow {
        const int* ray;
        const float* weight;
        int count;
    };
    WeightRow irradianceRow(int texel) const {
        const int a = irr_.start[std::size_t(texel)], b = irr_.start[std::size_t(texel) + 1];
        return {irr_.ray.data() + a, irr_.weight.data() + a, b - a};
    }

private:
    struct Sparse { // compressed rows: texel t uses entries [start[t], start[t+1])
        std::vector<int> start, ray;
        std::vector<float> weight;
    };
    int rays_;
    Parts parts_;
    Sparse irr_; // weights include pi / sum
    Sparse vis_; // weights include 1 / sum; empty with IrradianceOnly
    std::vector<float> shBasis_; // rays x kShL2Coefficients
    static void build(const std::vector<glm::vec3>& dirs, int interior, float scale, bool power,
                      Sparse& out);
};

} // namespace pb::probes
