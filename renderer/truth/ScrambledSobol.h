#pragma once
// The truth's random numbers: a pixel's samples are stratified, not independent.
//
// Why: at 1024 samples per pixel an independent-sample truth of rooms is still grainy enough
// that two seeds differ by LDR-FLIP 0.027 (2026-12-03), most of issue 43's 0.03 target for the
// reference's error against it. The integrand's hardest part is where a bounce lands (a sunlit
// patch seen or missed); stratifying each pair of dimensions over a pixel's samples lets the
// error of such a discontinuous 2D integral fall like n^-3/4 instead of n^-1/2.
//
// How: every request for random numbers on a path (the pixel jitter, the emitter pick, each
// bounce's direction, each roulette) takes the next dimension pair. Each pair is the first two
// dimensions of Sobol's sequence, a (0,2)-sequence: any 2^k consecutive points aligned to 2^k
// form a (0,k,2)-net, one point in each of 2^k elementary boxes. Each pair gets its own
// Owen scrambling and its own shuffle of the sample index, both by hashing (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4)): the scrambled points stay a net, the
// shuffle decorrelates one pair's strata from the next (Kollig and Keller's padding). Every
// point is uniformly distributed, so the estimator stays unbiased.
//
// Noise: stratified samples break the independent-sample variance formula. A pixel's samples
// are split into kBatches independently scrambled batches (sample s is in batch s % kBatches),
// whose means are independent and unbiased: their spread is an honest estimate of the pixel
// mean's variance (PathTracer.cpp).
#include <cstdint>

namespace pb::truth {

// Independent randomisations per pixel (the variance estimate's batches).
constexpr int kBatches = 4;

// Bit k of the result is bit 31-k of x.
std::uint32_t reverseBits32(std::uint32_t x);

// Sobol's first two dimensions of point i as 32-bit fixed-point fractions: dimension 0 is the
// van der Corput sequence (i's bits mirrored), dimension 1 uses the direction numbers of the
// primitive polynomial x + 1 (v_1 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1)).
std::uint32_t sobolDimension0(std::uint32_t i);
std::uint32_t sobolDimension1(std::uint32_t i);

// An Owen scrambling of a 32-bit fraction by hashing: bit k (from the top) of the result
// depends only on bits above and at k of the input and on the seed, so the image of any
// elementary interval is an elementary interval of the same size (nets stay nets).
std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed);

// The random numbers of one camera sample: sample `sample` of pixel `pixel` under `seed`.
// Deterministic in (seed, pixel, sample) and the order of requests.
class PathSampler {
public:
    PathSampler(std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample);

    // One number in [0, 1) (the first coordinate of the next dimension pair).
    float next1D();
    // Two numbers in [0, 1) from the next dimension pair.
    void next2D(float& u, float& v);

private:
    std::uint64_t key_;       // (seed, pixel, batch)
    std::uint32_t index_;     // the sample's index within its batch
    std::uint32_t pair_ = 0;  // the next dimension pair
};

} // namespace pb::truth
