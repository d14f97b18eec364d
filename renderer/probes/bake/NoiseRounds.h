#pragma once
// The converged bake's bookkeeping (BakeSettings::noiseTarget): per probe of a slab, its round
// count, its mean luminance and, per interior texel, the sum and sum of squares of the rounds'
// luminance. The estimated relative noise (standard error of the mean over its rounds, RMS over
// the texels, over the mean luminance) is
//   after 1 round:   sqrt(mean_t var_t) / mean_t Y(E_t), var_t from the round's own samples
//                    (RadianceSlab::texelVariance: as if the rays were independent, which
//                    overestimates for the stratified Fibonacci rays - so it only decides
//                    whether a second round is worth tracing);
//   after K >= 2:    sqrt(mean_t s_t^2 / K) / mean_t Y(E_t), s_t^2 the sample variance of
//                    the K rounds' values (independent rotations: what the seed changes).
// Every traced probe's final figure goes into the bake's statistics (BakeStats: mean, p95).
// Methods taking a probe index may run on several threads for distinct indices.
#include "probes/bake/Baker.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RadiancePass.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

class NoiseRounds {
public:
    explicit NoiseRounds(float target) : target_(target) {}
    // More rounds are traced only under a target; the noise is measured either way.
    bool active() const { return target_ > 0.0f; }

    void startSlab(std::size_t count);
    // Probe i's first round: slab slot i, already convolved into rgb (interior texels, RGB).
    void firstRound(std::size_t i, const RadianceSlab& slab, const ProbeConvolution& conv,
                    const float* rgb);
    // The slab's traced probes still above the target with rounds left.
    std::vector<std::size_t> aboveTarget(std::size_t count) const;
    // Adds a further round's texels (interior, RGB) to probe i; returns its round count.
    int addRound(std::size_t i, const float* rgb);
    // Probe i's mean luminance from its tile's interior (RGBA, pitch in texels).
    void setMean(std::size_t i, const float* tile, int pitch);
    // Records the slab's final figures.
    void finishSlab(std::size_t count);
    void summarise(BakeStats& stats) const;

    std::uint64_t extraRays = 0; // primary rays of rounds after the first

private:
    float noise(std::size_t i) const;
    float target_;
    std::vector<float> firstVariance_; // [probe * texels + t], of the first round
    std::vector<double> sumY_, sumY2_; // [probe * texels + t], over the rounds
    std::vector<float> meanY_;
    std::vector<int> rounds_; // 0: not traced
    std::vector<float> finals_;
    std::size_t multiRound_ = 0, aboveAfterAll_ = 0;
};

} // namespace pb::probes
