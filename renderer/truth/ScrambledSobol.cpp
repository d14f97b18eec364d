#include "truth/ScrambledSobol.h"

#include "core/Hash.h"

namespace pb::truth {
namespace {

std::uint64_t mix64(std::uint64_t x) { return splitmix64(x); } // x mixed (x itself is a copy)

// Laine and Karras's hash in bit-reversed order: adding and multiplying by even constants only
// carries from low bits to high bits, so after the reversal each bit depends on the bits above
// it (the nested uniform scrambling's structure, Burley 2020).
std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

float toUnit(std::uint32_t x) { return float(x >> 8) * (1.0f / 16777216.0f); } // [0, 1)

} // namespace

std::uint32_t reverseBits32(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

std::uint32_t sobolDimension0(std::uint32_t i) { return reverseBits32(i); }

std::uint32_t sobolDimension1(std::uint32_t i) {
    std::uint32_t result = 0;
    for (std::uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
        if (i & 1u) result ^= v;
    return result;
}

std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits32(laineKarras(reverseBits32(x), seed));
}

PathSampler::PathSampler(std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample)
    : key_(mix64(seed ^ mix64(pixel ^ mix64(std::uint64_t(sample % kBatches) + 0x5851f42d4c957f2dull)))),
      index_(sample / kBatches) {}

void PathSampler::next2D(float& u, float& v) {
    const std::uint64_t h = mix64(key_ ^ mix64(std::uint64_t(pair_++)));
    const std::uint64_t h2 = mix64(h);
    // The index shuffle is the same scrambling applied to the index: each bit depends on the
    // bits above it, so the indices below 2^k map onto one aligned block of 2^k indices, one
    // to one, and a pixel's first 2^k samples in a batch stay a net of their pair.
    const std::uint32_t i = owenScramble(index_, std::uint32_t(h));
    u = toUnit(owenScramble(sobolDimension0(i), std::uint32_t(h >> 32)));
    v = toUnit(owenScramble(sobolDimension1(i), std::uint32_t(h2)));
}

float PathSampler::next1D() {
    float u, v;
    next2D(u, v);
    return u;
}

} // namespace pb::truth
