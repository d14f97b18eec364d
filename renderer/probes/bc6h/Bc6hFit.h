#pragma once
// Private to the BC6H encoder: endpoint fitting, index selection and packing for one block.
//
// Error space: the decoder interpolates 16-bit integers and reinterprets (i * 31) >> 6 as the
// bits of a half float, so half-float bit patterns are the space the format is linear in. For
// normal numbers a step of 1 there is one half ulp, a relative step of 2^-11..2^-10: squared
// error in that space is a log-like (relative) HDR error, and it is exactly what the format
// can represent. Every choice (endpoints, indices, mode, partition) minimises the sum over the
// 16 texels and 3 channels of (decoded bits - source bits)^2, the source taken as continuous
// "fractional half bits" so no rounding happens before the comparison.
#include "probes/bc6h/Bc6hFormat.h"

#include <cstdint>
#include <limits>

namespace pb::probes::bc6h {

// The top of the 16-bit interpolation domain: fitted endpoints are clamped to [0, kMaxInterp].
constexpr float kMaxInterp = 65535.0f;

// One 4x4 block prepared for fitting.
struct BlockTarget {
    float h[16][3]; // source as continuous half-float bit patterns (the error space)
    float q[16][3]; // value in the 16-bit interpolation domain that decodes nearest to h
};

// Continuous half-float bit pattern of a value already clamped to [0, 65504].
float halfBitsContinuous(float v);
void prepareTarget(const float* texels /*16 x 3*/, BlockTarget& out);

struct Encoding {
    int mode = kFirstSingleRegionMode;
    int partition = 0;
    int ep[4][3] = {}; // quantised endpoints, absolute epb-bit values
    std::uint8_t index[16] = {};
    float error = std::numeric_limits<float>::infinity();
};

// Continuous endpoints (16-bit interpolation domain) of up to two subsets.
struct Lines {
    float e[4][3] = {};
};

// Principal-axis fit of the texels in `mask` (bit t = texel t) for subset `subset`, oriented
// so the anchor texel lies nearest the first endpoint (its index then needs no high bit).
void fitSubset(const BlockTarget& t, std::uint16_t mask, int anchor, int subset, Lines& out);

// Cheap score of a two-region partition: residual off each subset's principal axis plus an
// estimate of the 3-bit quantisation error along it (same units as Encoding::error). Ignores
// endpoint quantisation, so it is a ranking and a lower-bound-like guess, not a promise.
class PartitionEstimator {
public:
    explicit PartitionEstimator(const BlockTarget& t);
    // Scores of the 32 partitions; +inf for those whose score cannot be below `limit` (a
    // cheap lower bound rules them out before the eigenvalue work).
    void scores(float limit, float out[32]) const;

private:
    float texel_[9][16]; // per texel: centred value and its second moments
    float total_[9] = {};
};

// Quantises continuous endpoints for enc.mode, clamping deltas the mode cannot represent;
// returns false when it had to clamp.
bool quantizeEndpoints(const Lines& lines, Encoding& enc);

// Nearest epb-bit values of the continuous endpoints, no delta constraint applied (what
// quantizeEndpoints starts from; shared by all modes of one precision).
void quantizeAbsolute(const Lines& lines, int epb, int regions, int out[4][3]);
// Whether enc's absolute endpoints fit its mode's delta bits.
bool deltasRepresentable(const Encoding& enc);

// Chooses the best index of every texel for enc's endpoints, fixes the anchors (swapping a
// subset's endpoints when that is representable, otherwise restricting the anchor index) and
// returns the block error (also stored in enc.error).
float evaluate(const BlockTarget& t, Encoding& enc);

// Least-squares refit of the endpoints for the current indices, repeated `iterations` times;
// keeps the result only where it lowers the error.
void refine(const BlockTarget& t, Encoding& enc, int iterations);

// Tries +-1 on every quantised endpoint channel while that lowers the error.
void perturb(const BlockTarget& t, Encoding& enc, int passes);

void pack(const Encoding& enc, std::uint8_t out[16]);

} // namespace pb::probes::bc6h
