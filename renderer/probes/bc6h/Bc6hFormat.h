#pragma once
// Private to the BC6H encoder/decoder: the block format tables of the Khronos Data Format
// Specification (BPTC chapter, BC6H section) and the bit-level helpers both sides share, so
// the encoder packs exactly the layout the decoder reads.
//
// Modes are numbered 0..13 here in the order of Microsoft's documentation (its "mode 1..14"):
// 0..9 are the two-region modes, 10 (MS mode 11) is the single-region 10-bit mode, 11..13 the
// single-region delta modes. `code` is the 2- or 5-bit value stored in the block, which is the
// mode number the Khronos tables use.
#include <cstdint>

namespace pb::probes::bc6h {

constexpr int kModeCount = 14;
constexpr int kFirstSingleRegionMode = 10;

struct ModeInfo {
    int code;         // value of the low 2 (codes 0, 1) or 5 bits of the block
    int regions;      // 1 or 2
    bool transformed; // endpoints 1..3 are signed deltas from endpoint 0
    int epb;          // endpoint precision in bits
    int delta[3];     // delta bits per channel (transformed modes)
};

const ModeInfo& modeInfo(int mode);

// -1 for the reserved codes (19, 23, 27, 31), which decode to black.
int modeFromBlock(const std::uint8_t block[16]);

// Where each header bit goes: endpoint value fields 0..11 are R0 G0 B0 R1 G1 B1 R2 G2 B2 R3
// G3 B3 (endpoint * 3 + channel), field 12 is the partition number, kModeField the mode code.
constexpr std::uint8_t kPartitionField = 12;
constexpr std::uint8_t kModeField = 255;
struct FieldBit {
    std::uint8_t field;
    std::uint8_t bit;
};
// 82 entries for two-region modes, 65 for single-region modes.
const FieldBit* headerLayout(int mode);
inline int headerBits(int regions) {
    return regions == 2 ? 82 : 65;
}

// Two-region partitions 0..31 (the first half of the BPTC two-subset table): bit t set means
// texel t (= x + 4y) belongs to subset 1. Anchor = the texel of subset 1 whose index has one
// implicit (zero) high bit; subset 0's anchor is always texel 0.
extern const std::uint16_t kPartitions[32];
extern const std::uint8_t kAnchor2[32];

extern const int kWeights3[8];
extern const int kWeights4[16];

// Unsigned unquantisation of an epb-bit endpoint to the 16-bit interpolation domain.
inline int unquantize(int x, int epb) {
    if (epb >= 15) return x;
    if (x == 0) return 0;
    if (x == (1 << epb) - 1) return 0xFFFF;
    return ((x << 15) + 0x4000) >> (epb - 1);
}

inline int interpolate(int e0, int e1, int weight) {
    return ((64 - weight) * e0 + weight * e1 + 32) >> 6;
}

// Final unsigned scale: maps 0..0xFFFF onto the half-float bit patterns 0..0x7BFF (0..65504).
inline int finishUnsigned(int interpolated) {
    return (interpolated * 31) >> 6;
}

// What the encoder does to its input (and the error report to the reference): BC6H unsigned
// has no sign, NaN or infinity, so NaN and negatives become 0 and anything above the largest
// half float (including +inf) becomes 65504.
inline float clampSource(float v) {
    if (!(v > 0.0f)) return 0.0f;
    return v > 65504.0f ? 65504.0f : v;
}

// 128-bit little-endian block.
struct Bits128 {
    std::uint64_t lo = 0;
    std::uint64_t hi = 0;

    static Bits128 load(const std::uint8_t* bytes);
    void store(std::uint8_t* bytes) const;

    int bit(int pos) const {
        return static_cast<int>(((pos < 64 ? lo >> pos : hi >> (pos - 64))) & 1u);
    }
    void setBit(int pos, int value) {
        if (!value) return;
        if (pos < 64)
            lo |= std::uint64_t{1} << pos;
        else
            hi |= std::uint64_t{1} << (pos - 64);
    }
    int bits(int pos, int count) const {
        int v = 0;
        for (int i = 0; i < count; ++i)
            v |= bit(pos + i) << i;
        return v;
    }
    void setBits(int pos, int count, int value) {
        for (int i = 0; i < count; ++i)
            setBit(pos + i, (value >> i) & 1);
    }
};

} // namespace pb::probes::bc6h
