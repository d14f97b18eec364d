#include "scene/ImageHeader.h"

#include <algorithm>
#include <cstring>

namespace pb::scene {

namespace {

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 |
           std::uint32_t(p[3]);
}

std::uint32_t bigEndian16(const unsigned char* p) {
    return std::uint32_t(p[0]) << 8 | std::uint32_t(p[1]);
}

// PNG: 8-byte signature, then the IHDR chunk (length, "IHDR", width, height, ...), big-endian.
void readPng(const unsigned char* b, std::size_t size, ImageHeader& out) {
    if (size < 24 || std::memcmp(b + 12, "IHDR", 4) != 0) return;
    out.width = bigEndian32(b + 16);
    out.height = bigEndian32(b + 20);
}

// JPEG: a chain of segments, each 0xFF <marker> <16-bit length incl. itself> <payload>; the
// first start-of-frame segment (SOF0..SOF15 except DHT C4, JPG C8, DAC CC) holds precision,
// height, width. Markers without a payload: SOI D8, TEM 01, RST0-7 D0-D7. After a start of
// scan (DA) come entropy-coded bytes (0xFF stuffed as FF 00) up to the next marker; later
// segments (more scans, more tables) follow in progressive files. All of them are walked:
// every Huffman table (DHT) must hold at most 256 codes, since Debian's stb_image (2022-09)
// writes a table's code sizes into a 257-byte array without checking the count.
void readJpeg(const unsigned char* b, std::size_t size, ImageHeader& out) {
    std::size_t pos = 2;
    while (pos + 1 < size) {
        if (b[pos] != 0xFF) { // entropy-coded data (or junk): on to the next marker
            ++pos;
            continue;
        }
        const unsigned char marker = b[pos + 1];
        if (marker == 0xFF) { // fill byte
            ++pos;
            continue;
        }
        pos += 2;
        if (marker == 0x00 || marker == 0xD8 || marker == 0x01 ||
            (marker >= 0xD0 && marker <= 0xD7))
            continue;                                 // stuffed 0xFF, or a marker without a payload
        if (marker == 0xD9 || pos + 2 > size) return; // end of image or of the bytes
        const std::uint32_t length = bigEndian16(b + pos);
        if (length < 2) return;
        const unsigned char* payload = b + pos + 2;
        const std::size_t payloadSize = std::min<std::size_t>(length - 2, size - pos - 2);
        const bool startOfFrame =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (startOfFrame && out.width == 0 && payloadSize >= 5) {
            out.height = bigEndian16(payload + 1);
            out.width = bigEndian16(payload + 3);
        }
        if (marker == 0xC4) { // tables: class/id byte, 16 code counts, the symbols
            for (std::size_t t = 0; t + 17 <= payloadSize;) {
                std::size_t codes = 0;
                for (int i = 1; i <= 16; ++i)
                    codes += payload[t + std::size_t(i)];
                if (codes > 256) {
                    out.problem = "a Huffman table with more than 256 codes";
                    return;
                }
                t += 17 + codes;
            }
        }
        pos += length;
    }
}

} // namespace

ImageHeader readImageHeader(const unsigned char* bytes, std::size_t size) {
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    ImageHeader out;
    if (size >= 8 && std::memcmp(bytes, kPng, 8) == 0) {
        out.kind = ImageHeader::Kind::Png;
        readPng(bytes, size, out);
    } else if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) {
        out.kind = ImageHeader::Kind::Jpeg;
        readJpeg(bytes, size, out);
    }
    return out;
}

} // namespace pb::scene
