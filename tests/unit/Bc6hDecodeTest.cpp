// BC6H decoder against blocks built bit by bit from the tables of the Khronos Data Format
// Specification (BPTC, "Interpretation of lower/upper bits for BC6H block modes"); expected
// values worked out from the specification's formulas: unquantise, ((64-w)*e0 + w*e1 + 32)>>6,
// then (i*31)>>6 read as a half float. Mode names follow Microsoft's numbering (1..14); the
// block code the Khronos table uses is given beside each.
#include "probes/bc6h/Bc6h.h"

#include "core/Error.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace {

using pb::probes::decodeBc6hUf16;
using pb::probes::decodeBc6hUf16Block;

struct BlockBuilder {
    std::array<std::uint8_t, 16> bytes{};

    // `count` bits of `value`, least significant first, at block bit `pos`.
    void put(int pos, int count, int value) {
        for (int i = 0; i < count; ++i)
            if ((value >> i) & 1)
                bytes[(pos + i) / 8] |= static_cast<std::uint8_t>(1u << ((pos + i) % 8));
    }
    // One bit: bit `bit` of `value`.
    void putBit(int pos, int value, int bit) { put(pos, 1, (value >> bit) & 1); }

    // Indices from `start`, `bits` per texel, one bit less for the anchor texels.
    void putIndices(int start, int bits, const int (&index)[16], int anchor2 = -1) {
        int pos = start;
        for (int t = 0; t < 16; ++t) {
            const int n = (t == 0 || t == anchor2) ? bits - 1 : bits;
            put(pos, n, index[t]);
            pos += n;
        }
        EXPECT_EQ(pos, 128);
    }
};

struct Expect {
    int texel;
    float r, g, b;
};

void expectTexels(const BlockBuilder& block, std::initializer_list<Expect> expected) {
    float out[48];
    decodeBc6hUf16Block(block.bytes.data(), out);
    for (const Expect& e : expected) {
        SCOPED_TRACE("texel " + std::to_string(e.texel));
        EXPECT_EQ(out[e.texel * 3 + 0], e.r);
        EXPECT_EQ(out[e.texel * 3 + 1], e.g);
        EXPECT_EQ(out[e.texel * 3 + 2], e.b);
    }
}

constexpr int kRamp16[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

// Mode 11 (code 3): one region, plain 10-bit endpoints, bits 5..64, indices from bit 65.
TEST(Bc6hDecode, Mode11Plain10Bit) {
    BlockBuilder b;
    b.put(0, 5, 3);
    b.put(5, 10, 0);     // R0
    b.put(15, 10, 1023); // G0
    b.put(25, 10, 512);  // B0
    b.put(35, 10, 1023); // R1
    b.put(45, 10, 0);    // G1
    b.put(55, 10, 100);  // B1
    b.putIndices(65, 4, kRamp16);
    // Texel 5, R: unq(0)=0, unq(1023)=0xFFFF (the all-ones special case), weight 21:
    // (21*65535+32)>>6 = 21504; (21504*31)>>6 = 10416 = 0x28B0 = 2^-5 * (1 + 176/1024).
    // B: unq(512) = ((512<<15)+0x4000)>>9 = 32800, unq(100) = 6432.
    expectTexels(b, {{0, 0.0f, 65504.0f, 1.5146484375f},
                     {5, 0.03662109375f, 58.46875f, 0.0888671875f},
                     {15, 65504.0f, 0.0f, 0.0002543926239013672f}});
}

// Mode 12 (code 7): 11-bit base, 9-bit signed deltas; bits 44, 54, 64 are R0/G0/B0 bit 10.
TEST(Bc6hDecode, Mode12Delta9Bit) {
    BlockBuilder b;
    b.put(0, 5, 7);
    b.put(5, 10, 1500 & 1023);
    b.put(15, 10, 3);
    b.put(25, 10, 2047 & 1023);
    b.put(35, 9, -200 & 511); // R1 = 1500 - 200 = 1300
    b.putBit(44, 1500, 10);
    b.put(45, 9, 255); // G1 = 3 + 255 = 258 (largest positive delta)
    b.putBit(54, 3, 10);
    b.put(55, 9, -256 & 511); // B1 = 2047 - 256 = 1791 (most negative delta)
    b.putBit(64, 2047, 10);
    b.putIndices(65, 4, kRamp16);
    expectTexels(b, {{0, 219.125f, 3.2186508178710938e-06f, 65504.0f},
                     {7, 82.75f, 0.00011360645294189453f, 19328.0f},
                     {15, 26.953125f, 0.0004668235778808594f, 4576.0f}});
}

// Mode 13 (code 11): 12-bit base, 8-bit deltas; base bits 11 then 10 stored reversed.
TEST(Bc6hDecode, Mode13Delta8BitReversedHighBitsAndWrap) {
    BlockBuilder b;
    b.put(0, 5, 11);
    b.put(5, 10, 2100 & 1023);
    b.put(15, 10, 4090 & 1023);
    b.put(25, 10, 1100 & 1023);
    b.put(35, 8, -128 & 255); // R1 = 2100 - 128 = 1972
    b.putBit(43, 2100, 11);
    b.putBit(44, 2100, 10);
    b.put(45, 8, 100); // G1 = (4090 + 100) mod 4096 = 94: deltas wrap
    b.putBit(53, 4090, 11);
    b.putBit(54, 4090, 10);
    b.put(55, 8, 5); // B1 = 1105
    b.putBit(63, 1100, 11);
    b.putBit(64, 1100, 10);
    b.putIndices(65, 4, kRamp16);
    expectTexels(b, {{0, 1.896484375f, 64160.0f, 0.0103759765625f},
                     {9, 1.3212890625f, 0.250244140625f, 0.01055908203125f},
                     {15, 0.9638671875f, 4.363059997558594e-05f, 0.01067352294921875f}});
}

// Mode 14 (code 15): 16-bit base (no unquantisation), 4-bit deltas; base bits 15..10 reversed.
TEST(Bc6hDecode, Mode14Delta4Bit16BitBase) {
    const int r0 = 0xBC01, g0 = 0x3C00, b0 = 0xFFFF;
    BlockBuilder b;
    b.put(0, 5, 15);
    b.put(5, 10, r0 & 1023);
    b.put(15, 10, g0 & 1023);
    b.put(25, 10, b0 & 1023);
    b.put(35, 4, -8 & 15);
    for (int k = 0; k < 6; ++k)
        b.putBit(39 + k, r0, 15 - k);
    b.put(45, 4, 7);
    for (int k = 0; k < 6; ++k)
        b.putBit(49 + k, g0, 15 - k);
    b.put(55, 4, -1 & 15);
    for (int k = 0; k < 6; ++k)
        b.putBit(59 + k, b0, 15 - k);
    b.putIndices(65, 4, kRamp16);
    expectTexels(b, {{0, 226.0f, 0.00494384765625f, 65504.0f},
                     {3, 225.875f, 0.00494384765625f, 65504.0f},
                     {15, 225.5f, 0.004955291748046875f, 65504.0f}});
}

// Mode 10 (code 30): two regions, plain 6-bit endpoints, partition 17 (anchor texel 2).
TEST(Bc6hDecode, Mode10TwoRegionsPlain6Bit) {
    const int e[4][3] = {{63, 0, 10}, {0, 63, 20}, {32, 16, 63}, {1, 62, 0}};
    BlockBuilder b;
    b.put(0, 5, 30);
    b.put(5, 6, e[0][0]);
    b.putBit(11, e[3][1], 4);
    b.putBit(12, e[3][2], 0);
    b.putBit(13, e[3][2], 1);
    b.putBit(14, e[2][2], 4);
    b.put(15, 6, e[0][1]);
    b.putBit(21, e[2][1], 5);
    b.putBit(22, e[2][2], 5);
    b.putBit(23, e[3][2], 2);
    b.putBit(24, e[2][1], 4);
    b.put(25, 6, e[0][2]);
    b.putBit(31, e[3][1], 5);
    b.putBit(32, e[3][2], 3);
    b.putBit(33, e[3][2], 5);
    b.putBit(34, e[3][2], 4);
    b.put(35, 6, e[1][0]);
    b.put(41, 4, e[2][1] & 15);
    b.put(45, 6, e[1][1]);
    b.put(51, 4, e[3][1] & 15);
    b.put(55, 6, e[1][2]);
    b.put(61, 4, e[2][2] & 15);
    b.put(65, 6, e[2][0]);
    b.put(71, 6, e[3][0]);
    b.put(77, 5, 17);
    // Partition 17 puts texels 1, 2, 3, 7 in subset 1; texels 0 and 2 store 2 index bits.
    const int index[16] = {0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7};
    b.putIndices(82, 3, index, 2);
    // Texel 12, subset 0, index 4 (weight 37), R: unq(63)=0xFFFF, unq(0)=0:
    // (27*65535+32)>>6 = 27648; (27648*31)>>6 = 13392 = 0x3450 = 0.26953125.
    expectTexels(b, {{0, 65504.0f, 0.0f, 0.00106048583984375f},
                     {1, 0.407470703125f, 0.0703125f, 3358.0f},
                     {2, 0.09490966796875f, 0.62939453125f, 163.875f},
                     {7, 4.4345855712890625e-05f, 41728.0f, 0.0f},
                     {12, 0.26953125f, 7.68359375f, 0.007366180419921875f}});
}

// Mode 1 (code 0, two mode bits): two regions, 10-bit base, 5-bit deltas, partition 0.
TEST(Bc6hDecode, Mode1TwoRegionsDelta5Bit) {
    const int e0[3] = {1000, 5, 512};
    const int d[4][3] = {{0, 0, 0}, {-16, 15, 0}, {3, -8, -16}, {7, 8, 15}}; // E1..E3 deltas
    auto v = [&](int endpoint, int c) { return endpoint == 0 ? e0[c] : d[endpoint][c] & 31; };
    BlockBuilder b;
    b.put(0, 2, 0);
    b.putBit(2, v(2, 1), 4);
    b.putBit(3, v(2, 2), 4);
    b.putBit(4, v(3, 2), 4);
    b.put(5, 10, e0[0]);
    b.put(15, 10, e0[1]);
    b.put(25, 10, e0[2]);
    b.put(35, 5, v(1, 0));
    b.putBit(40, v(3, 1), 4);
    b.put(41, 4, v(2, 1) & 15);
    b.put(45, 5, v(1, 1));
    b.putBit(50, v(3, 2), 0);
    b.put(51, 4, v(3, 1) & 15);
    b.put(55, 5, v(1, 2));
    b.putBit(60, v(3, 2), 1);
    b.put(61, 4, v(2, 2) & 15);
    b.put(65, 5, v(2, 0));
    b.putBit(70, v(3, 2), 2);
    b.put(71, 5, v(3, 0));
    b.putBit(76, v(3, 2), 3);
    b.put(77, 5, 0);
    // Decoded endpoints: E1 = (984, 20, 512), E2 = (1003, 1021 (5-8 wraps), 496),
    // E3 = (1007, 13, 527). Partition 0: columns 2, 3 are subset 1; anchor texel 15.
    const int index[16] = {0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 3};
    b.putIndices(82, 3, index, 15);
    expectTexels(b, {{0, 42208.0f, 1.0132789611816406e-05f, 1.5146484375f},
                     {2, 46304.0f, 171.75f, 1.2939453125f},
                     {5, 31792.0f, 3.0040740966796875e-05f, 1.5146484375f},
                     {15, 46848.0f, 8.3984375f, 1.42578125f}});
}

TEST(Bc6hDecode, ReservedModesDecodeToBlack) {
    for (int code : {19, 23, 27, 31}) {
        BlockBuilder b;
        b.bytes.fill(0xA5);
        b.bytes[0] = static_cast<std::uint8_t>((0xA5 & ~31) | code);
        float out[48];
        decodeBc6hUf16Block(b.bytes.data(), out);
        for (float v : out)
            EXPECT_EQ(v, 0.0f) << "code " << code;
    }
}

TEST(Bc6hDecode, TextureLayoutIsRowMajorBlocks) {
    // 8x4 texture: block 0 is all 0, block 1 is mode 11 with both endpoints 1023 (65504).
    std::array<std::uint8_t, 32> data{};
    BlockBuilder white;
    white.put(0, 5, 3);
    for (int f = 0; f < 6; ++f)
        white.put(5 + 10 * f, 10, 1023);
    data[0] = 3; // mode 11 with zero endpoints
    std::copy(white.bytes.begin(), white.bytes.end(), data.begin() + 16);
    const std::vector<float> rgb = decodeBc6hUf16(data.data(), 8, 4);
    ASSERT_EQ(rgb.size(), 8u * 4u * 3u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(rgb[(y * 8 + x) * 3 + 1], x < 4 ? 0.0f : 65504.0f) << x << "," << y;
}

TEST(Bc6hDecode, RejectsBadSizes) {
    const std::uint8_t block[16] = {3};
    EXPECT_THROW(decodeBc6hUf16(block, 4, 6), pb::Error);
    EXPECT_THROW(decodeBc6hUf16(block, 0, 4), pb::Error);
    EXPECT_THROW(decodeBc6hUf16(block, -4, 4), pb::Error);
}

} // namespace
