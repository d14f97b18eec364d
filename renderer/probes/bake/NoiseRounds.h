#pragma once
// The converged bake's bookkeeping (BakeSettings::noiseTarget), for the probe's FINAL
// irradiance: the first pass's light plus every later pass's increment (Baker.h). Per probe of
// a slab: its round count in this pass, the pass's mean luminance and, per interior texel, the
// sum and sum of squares of the rounds' luminance. The variance of this pass's estimate (RMS
// over the texels) is
//   after 1 round:   mean_t var_t, var_t from the round's own samples
//                    (RadianceSlab::texelVariance: as if the rays were independent, which
//                    overestimates for the stratified Fibonacci rays);
//   after K >= 2:    mean_t s_t^2 / K, s_t^2 the sample variance of the K rounds' values
//                    (independent rotations: what the seed changes).
// The passes' rays are independent, so a probe's final variance is the sum of its passes'
// (what the previous increment's noise adds through the lookups at the hits is left out: it is
// smoothed over the hits and scaled by the albedo). The relative noise is
//   sqrt(sum of the passes' variances) / max(mean luminance of all passes so far, floor),
// the floor a share (kNoiseFloorShare) of the scenario's mean probe luminance after the first
// pass: a probe next to nothing (outside a closed room) is not "100% noisy" for a few stray
// photons, and gets no rounds chasing them.
// Each pass's rounds stop once the probe's final noise, so estimated, is below the target.
// Every traced probe's final figure goes into the bake's statistics (BakeStats: mean, p95).
// Methods taking a probe index may run on several threads for distinct indices.
#include "probes/bake/Baker.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RadiancePass.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// The luminance below which a probe's relative noise is taken against this share of the
// scenario's mean probe luminance instead of its own.
constexpr float kNoiseFloorShare = 0.02f;

class NoiseRounds {
public:
    explicit NoiseRounds(float target) : target_(target) {}
    // More rounds are traced only under a target; the noise is measured either way.
    bool active() const { return target_ > 0.0f; }

    // A scenario's passes start: `probes` flat probe indices (ProbeIndex), nothing carried.
    void startScenario(std::size_t probes);
    // Probes first .. first + count - 1 of a pass.
    void startSlab(std::size_t first, std::size_t count);
    // Probe i's first round: slab slot i, already convolved into rgb (interior texels, RGB).
    void firstRound(std::size_t i, const RadianceSlab& slab, const ProbeConvolution& conv,
                    const float* rgb);
    // The slab's traced probes still above the target with rounds left.
    std::vector<std::size_t> aboveTarget(std::size_t count) const;
    // Adds a further round's texels (interior, RGB) to probe i; returns its round count.
    int addRound(std::size_t i, const float* rgb);
    // Probe i's mean luminance from its tile's interior (RGBA, pitch in texels).
    void setMean(std::size_t i, const float* tile, int pitch);
    // Carries the slab's pass into each probe's final figures.
    void finishSlab(std::size_t count);
    // After the first pass: the floor, from the traced probes' mean luminance.
    void setFloorFromCarried();
    // Records every traced probe's final noise.
    void finishScenario();
    void summarise(BakeStats& stats) const;
    // The flat indices of the probes above the target after every pass and round (once per
    // scenario that left them there).
    const std::vector<std::size_t>& aboveTargetProbes() const { return aboveFlat_; }

    std::uint64_t extraRays = 0; // primary rays of rounds after the first

private:
    float passVariance(std::size_t i) const; // this pass's, of probe i of the slab
    float finalNoise(std::size_t flat, float passVar, float passMean) const;
    float target_;
    float floor_ = 0.0f;
    std::size_t first_ = 0;
    std::vector<float> firstVariance_; // [probe * texels + t], of the first round
    std::vector<double> sumY_, sumY2_; // [probe * texels + t], over the rounds
    std::vector<float> meanY_;
    std::vector<int> rounds_; // 0: not traced
    // Per flat probe, over the scenario's passes so far: variance and mean luminance.
    std::vector<double> carriedVar_, carriedMean_;
    std::vector<std::uint8_t> traced_;
    std::vector<float> finals_;
    std::vector<std::size_t> aboveFlat_;
    std::size_t multiRound_ = 0, probePasses_ = 0, aboveAfterAll_ = 0;
};

} // namespace pb::probes
