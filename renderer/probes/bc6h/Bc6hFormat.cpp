#include "probes/bc6h/Bc6hFormat.h"

#include <array>
#include <cstdlib>
#include <string_view>

namespace pb::probes::bc6h {
namespace {

// clang-format off
const ModeInfo kModes[kModeCount] = {
    { 0, 2, true, 10, {5, 5, 5}}, { 1, 2, true,  7, {6, 6, 6}},
    { 2, 2, true, 11, {5, 4, 4}}, { 6, 2, true, 11, {4, 5, 4}},
    {10, 2, true, 11, {4, 4, 5}}, {14, 2, true,  9, {5, 5, 5}},
    {18, 2, true,  8, {6, 5, 5}}, {22, 2, true,  8, {5, 6, 5}},
    {26, 2, true,  8, {5, 5, 6}}, {30, 2, false, 6, {0, 0, 0}},
    { 3, 1, false, 10, {0, 0, 0}}, { 7, 1, true, 11, {9, 9, 9}},
    {11, 1, true, 12, {8, 8, 8}}, {15, 1, true, 16, {4, 4, 4}},
};

// The block descriptions of the specification ("Block descriptions for BC6H block modes",
// LSB first, after the mode bits), written the way the table writes them: "R0:9-0" means the
// next ten block bits are R0 bits 0..9; "R0:10-11" means the next two are R0 bits 11 then 10
// (the reversed fields of modes 11 and 15). Kept as text so it can be read against the table.
const char* const kLayouts[kModeCount] = {
    "G2:4 B2:4 B3:4 R0:9-0 G0:9-0 B0:9-0 R1:4-0 G3:4 G2:3-0 G1:4-0 B3:0 G3:3-0 B1:4-0 B3:1 "
    "B2:3-0 R2:4-0 B3:2 R3:4-0 B3:3 PB:4-0",
    "G2:5 G3:4 G3:5 R0:6-0 B3:0 B3:1 B2:4 G0:6-0 B2:5 B3:2 G2:4 B0:6-0 B3:3 B3:5 B3:4 R1:5-0 "
    "G2:3-0 G1:5-0 G3:3-0 B1:5-0 B2:3-0 R2:5-0 R3:5-0 PB:4-0",
    "R0:9-0 G0:9-0 B0:9-0 R1:4-0 R0:10 G2:3-0 G1:3-0 G0:10 B3:0 G3:3-0 B1:3-0 B0:10 B3:1 "
    "B2:3-0 R2:4-0 B3:2 R3:4-0 B3:3 PB:4-0",
    "R0:9-0 G0:9-0 B0:9-0 R1:3-0 R0:10 G3:4 G2:3-0 G1:4-0 G0:10 G3:3-0 B1:3-0 B0:10 B3:1 "
    "B2:3-0 R2:3-0 B3:0 B3:2 R3:3-0 G2:4 B3:3 PB:4-0",
    "R0:9-0 G0:9-0 B0:9-0 R1:3-0 R0:10 B2:4 G2:3-0 G1:3-0 G0:10 B3:0 G3:3-0 B1:4-0 B0:10 "
    "B2:3-0 R2:3-0 B3:1 B3:2 R3:3-0 B3:4 B3:3 PB:4-0",
    "R0:8-0 B2:4 G0:8-0 G2:4 B0:8-0 B3:4 R1:4-0 G3:4 G2:3-0 G1:4-0 B3:0 G3:3-0 B1:4-0 B3:1 "
    "B2:3-0 R2:4-0 B3:2 R3:4-0 B3:3 PB:4-0",
    "R0:7-0 G3:4 B2:4 G0:7-0 B3:2 G2:4 B0:7-0 B3:3 B3:4 R1:5-0 G2:3-0 G1:4-0 B3:0 G3:3-0 "
    "B1:4-0 B3:1 B2:3-0 R2:5-0 R3:5-0 PB:4-0",
    "R0:7-0 B3:0 B2:4 G0:7-0 G2:5 G2:4 B0:7-0 G3:5 B3:4 R1:4-0 G3:4 G2:3-0 G1:5-0 G3:3-0 "
    "B1:4-0 B3:1 B2:3-0 R2:4-0 B3:2 R3:4-0 B3:3 PB:4-0",
    "R0:7-0 B3:1 B2:4 G0:7-0 B2:5 G2:4 B0:7-0 B3:5 B3:4 R1:4-0 G3:4 G2:3-0 G1:4-0 B3:0 "
    "G3:3-0 B1:5-0 B2:3-0 R2:4-0 B3:2 R3:4-0 B3:3 PB:4-0",
    "R0:5-0 G3:4 B3:0 B3:1 B2:4 G0:5-0 G2:5 B2:5 B3:2 G2:4 B0:5-0 G3:5 B3:3 B3:5 B3:4 "
    "R1:5-0 G2:3-0 G1:5-0 G3:3-0 B1:5-0 B2:3-0 R2:5-0 R3:5-0 PB:4-0",
    "R0:9-0 G0:9-0 B0:9-0 R1:9-0 G1:9-0 B1:9-0",
    "R0:9-0 G0:9-0 B0:9-0 R1:8-0 R0:10 G1:8-0 G0:10 B1:8-0 B0:10",
    "R0:9-0 G0:9-0 B0:9-0 R1:7-0 R0:10-11 G1:7-0 G0:10-11 B1:7-0 B0:10-11",
    "R0:9-0 G0:9-0 B0:9-0 R1:3-0 R0:10-15 G1:3-0 G0:10-15 B1:3-0 B0:10-15",
};
// clang-format on

using Layout = std::array<FieldBit, 82>;

int leadingNumber(std::string_view s) {
    int v = 0;
    for (std::size_t i = 0; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
        v = v * 10 + (s[i] - '0');
    return v;
}

// Parses one layout string; aborts on a malformed table (a programming error caught by the
// unit tests, never a user error).
Layout parseLayout(int mode) {
    Layout out{};
    const ModeInfo& info = kModes[mode];
    int pos = 0;
    const int modeBits = info.code < 2 ? 2 : 5;
    for (; pos < modeBits; ++pos)
        out[pos] = {kModeField, static_cast<std::uint8_t>(pos)};
    std::string_view text = kLayouts[mode];
    while (!text.empty()) {
        const std::size_t end = text.find(' ');
        const std::string_view token = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        std::uint8_t field = kPartitionField;
        if (token.substr(0, 2) != "PB") {
            const int channel = token[0] == 'R' ? 0 : token[0] == 'G' ? 1 : 2;
            field = static_cast<std::uint8_t>((token[1] - '0') * 3 + channel);
        }
        const std::size_t colon = token.find(':');
        const std::size_t dash = token.find('-');
        const int a = leadingNumber(token.substr(colon + 1));
        const int b = dash == std::string_view::npos ? a : leadingNumber(token.substr(dash + 1));
        const int step = a >= b ? 1 : -1;
        for (int v = b;; v += step) {
            if (pos >= 82) std::abort();
            out[pos++] = {field, static_cast<std::uint8_t>(v)};
            if (v == a) break;
        }
    }
    if (pos != headerBits(info.regions)) std::abort();
    return out;
}

} // namespace

// clang-format off
const std::uint16_t kPartitions[32] = {
    0xCCCC, 0x8888, 0xEEEE, 0xECC8, 0xC880, 0xFEEC, 0xFEC8, 0xEC80,
    0xC800, 0xFFEC, 0xFE80, 0xE800, 0xFFE8, 0xFF00, 0xFFF0, 0xF000,
    0xF710, 0x008E, 0x7100, 0x08CE, 0x008C, 0x7310, 0x3100, 0x8CCE,
    0x088C, 0x3110, 0x6666, 0x366C, 0x17E8, 0x0FF0, 0x718E, 0x399C,
};
const std::uint8_t kAnchor2[32] = {
    15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15,
    15,  2,  8,  2,  2,  8,  8, 15,  2,  8,  2,  2,  8,  8,  2,  2,
};
// clang-format on
const int kWeights3[8] = {0, 9, 18, 27, 37, 46, 55, 64};
const int kWeights4[16] = {0, 4, 9, 13, 17, 21, 26, 30, 34, 38, 43, 47, 51, 55, 60, 64};

const ModeInfo& modeInfo(int mode) {
    return kModes[mode];
}

int modeFromBlock(const std::uint8_t block[16]) {
    int code = block[0] & 3;
    if (code >= 2) code = block[0] & 31;
    for (int m = 0; m < kModeCount; ++m)
        if (kModes[m].code == code) return m;
    return -1;
}

const FieldBit* headerLayout(int mode) {
    static const std::array<Layout, kModeCount> layouts = [] {
        std::array<Layout, kModeCount> all{};
        for (int m = 0; m < kModeCount; ++m)
            all[m] = parseLayout(m);
        return all;
    }();
    return layouts[mode].data();
}

Bits128 Bits128::load(const std::uint8_t* bytes) {
    Bits128 b;
    for (int i = 0; i < 8; ++i) {
        b.lo |= std::uint64_t{bytes[i]} << (8 * i);
        b.hi |= std::uint64_t{bytes[8 + i]} << (8 * i);
    }
    return b;
}

void Bits128::store(std::uint8_t* bytes) const {
    for (int i = 0; i < 8; ++i) {
        bytes[i] = static_cast<std::uint8_t>(lo >> (8 * i));
        bytes[8 + i] = static_cast<std::uint8_t>(hi >> (8 * i));
    }
}

} // namespace pb::probes::bc6h
