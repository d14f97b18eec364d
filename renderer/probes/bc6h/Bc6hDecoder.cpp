// BC6H unsigned-float decoder, bit-exact to the Khronos Data Format Specification: the CPU
// reference the GPU's sampler is checked against (tests/gl/Bc6hGlTest.cpp) and what the bake
// measures compression error with.
#include "probes/bc6h/Bc6h.h"
#include "probes/bc6h/Bc6hFormat.h"

#include "core/Error.h"

#include <glm/gtc/packing.hpp>

#include <string>

namespace pb::probes {

using namespace bc6h;

namespace {

int signExtend(int value, int bits) {
    const int sign = 1 << (bits - 1);
    return (value & (sign - 1)) - (value & sign);
}

} // namespace

void decodeBc6hUf16Block(const std::uint8_t* block, float out[48]) {
    const int mode = modeFromBlock(block);
    if (mode < 0) {
        for (int i = 0; i < 48; ++i)
            out[i] = 0.0f; // reserved mode: black, as specified
        return;
    }
    const ModeInfo& info = modeInfo(mode);
    const Bits128 bits = Bits128::load(block);

    int fields[13] = {};
    const FieldBit* layout = headerLayout(mode);
    const int header = headerBits(info.regions);
    for (int pos = 0; pos < header; ++pos) {
        const FieldBit fb = layout[pos];
        if (fb.field != kModeField) fields[fb.field] |= bits.bit(pos) << fb.bit;
    }

    const int endpoints = 2 * info.regions;
    const int mask = (1 << info.epb) - 1;
    int unq[4][3];
    for (int e = 0; e < endpoints; ++e) {
        for (int c = 0; c < 3; ++c) {
            int v = fields[e * 3 + c];
            if (info.transformed && e > 0)
                v = (fields[c] + signExtend(v, info.delta[c])) & mask; // unsigned: E0 not extended
            unq[e][c] = unquantize(v, info.epb);
        }
    }

    const int partition = fields[kPartitionField];
    const std::uint16_t subsetMask = info.regions == 2 ? kPartitions[partition] : 0;
    const int anchor2 = info.regions == 2 ? kAnchor2[partition] : -1;
    const int indexBits = info.regions == 2 ? 3 : 4;
    const int* weights = info.regions == 2 ? kWeights3 : kWeights4;

    int pos = header;
    for (int t = 0; t < 16; ++t) {
        // Anchor texels store one bit less: their high index bit is implicitly zero.
        const int n = (t == 0 || t == anchor2) ? indexBits - 1 : indexBits;
        const int index = bits.bits(pos, n);
        pos += n;
        const int s = (subsetMask >> t) & 1;
        for (int c = 0; c < 3; ++c) {
            const int i = interpolate(unq[2 * s][c], unq[2 * s + 1][c], weights[index]);
            out[t * 3 + c] = glm::unpackHalf1x16(static_cast<glm::uint16>(finishUnsigned(i)));
        }
    }
}

std::vector<float> decodeBc6hUf16(const std::uint8_t* blocks, int width, int height) {
    if (width <= 0 || height <= 0 || width % 4 != 0 || height % 4 != 0)
        throw Error("BC6H decode: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not a positive multiple of 4");
    std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
    const int bw = width / 4;
    float texels[48];
    for (int by = 0; by < height / 4; ++by) {
        for (int bx = 0; bx < bw; ++bx) {
            decodeBc6hUf16Block(blocks + (static_cast<std::size_t>(by) * bw + bx) * 16, texels);
            for (int y = 0; y < 4; ++y) {
                float* row = rgb.data() + ((static_cast<std::size_t>(by) * 4 + y) * width +
                                           static_cast<std::size_t>(bx) * 4) *
                                              3;
                for (int i = 0; i < 12; ++i)
                    row[i] = texels[y * 12 + i];
            }
        }
    }
    return rgb;
}

} // namespace pb::probes
