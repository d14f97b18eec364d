#pragma once
// BC6H (BPTC unsigned float, GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT = 0x8E8F) encoder and
// decoder, written from the Khronos Data Format Specification (BPTC chapter). Probe irradiance
// (RGB) and visibility (mean distance, mean squared distance in R,G; B unused) are stored with
// it, as the reference talk does with BC6: 16 bytes per 4x4 block, 1 byte per texel.
//
// Layout: blocks in row-major order (block (bx,by) at index by*(width/4)+bx), 16 bytes each,
// exactly what glCompressedTexImage2D / glCompressedTexSubImage3D (one array layer) expect.
//
// Input domain: linear, non-negative floats. BC6H unsigned stores half floats without sign,
// so negative values and NaN become 0, and values above the half-float maximum (and +inf)
// clamp to 65504. The decoder is bit-exact to the specification (all 14 modes, both region
// counts, unquantisation and the final *31/64 scale), so CPU-measured error is the GPU's.
//
// Neither function touches GL. Both are deterministic (no threads, no randomness: the same
// input gives the same bytes for a given build; builds that contract float math into FMA,
// e.g. -std=gnu++20 on an FMA target, may pick different but equally valid blocks) and
// thread-compatible (no shared mutable state), so callers may encode slices in parallel.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pb::probes {

constexpr int kBc6hBlockBytes = 16;
constexpr unsigned kGlCompressedRgbBptcUnsignedFloat = 0x8E8F; // EXT suffix on GL ES

// Modes are Microsoft's numbers 1..14 (1-10 two regions, 11-14 one region). The encoder fits
// a principal axis in half-float bit space (where BC6H interpolates; a log-like space, one
// unit = one half ulp), refines endpoints by least squares and picks, per block, the mode and
// partition with the least squared error in that space.
//   Fast:   one region only (modes 11-14), the two most precise modes that fit.
//   Normal: also two regions on the 3 partitions ranked best by a principal-axis estimate,
//           skipped when that estimate cannot beat one region (most smooth blocks).
//   High:   8 partitions, every endpoint precision that fits, more refinement and a +-1
//           search on the quantised endpoints; never worse than Normal per block.
// Speed and error on a 32x8x32 probe volume: tests/unit/Bc6hPerfTest.cpp.
enum class Bc6hQuality { Fast, Normal, High };

// Bytes needed for a width x height texture (both multiples of 4).
std::size_t bc6hSizeBytes(int width, int height);

// rgb: height rows of width texels, strideFloats floats per texel (2, 3 or 4; with 2 the texel
// is (R,G) and B is encoded as 0 - handy for visibility; a 4th float is ignored).
// Throws pb::Error when width/height are not positive multiples of 4 or the stride is invalid.
std::vector<std::uint8_t> encodeBc6hUf16(const float* rgb, int width, int height, int strideFloats,
                                         Bc6hQuality q = Bc6hQuality::Normal);

// Decodes one 16-byte block to 16 texels of RGB (row-major inside the block, 48 floats).
void decodeBc6hUf16Block(const std::uint8_t* block, float out[48]);

// Decodes a whole texture to width*height*3 floats (row-major RGB). Reserved/invalid modes
// decode to 0, as the specification requires. Throws pb::Error on bad sizes.
std::vector<float> decodeBc6hUf16(const std::uint8_t* blocks, int width, int height);

// Error of decoded RGB (3 floats per texel) against the source (strideFloats per texel, the
// same clamping the encoder applies is applied to the source first). Relative error of one
// channel is |decoded - source| / max(source, relativeFloor): the floor keeps near-black
// values from dominating (an absolute error of 1e-4 on a value of 1e-6 is invisible).
// Channels not present in the source (B with stride 2) are skipped.
struct Bc6hErrorStats {
    double maxAbs = 0.0;
    double meanAbs = 0.0;
    double maxRel = 0.0;
    double meanRel = 0.0;
    double rmse = 0.0;
    std::size_t channels = 0; // number of channel values measured
};

Bc6hErrorStats measureBc6hError(const float* source, int strideFloats, const float* decodedRgb,
                                int width, int height, double relativeFloor = 1e-3);

// Convenience: encode, decode and measure in one call (what the bake report wants).
Bc6hErrorStats bc6hRoundTripError(const float* rgb, int width, int height, int strideFloats,
                                  Bc6hQuality q = Bc6hQuality::Normal, double relativeFloor = 1e-3);

} // namespace pb::probes
