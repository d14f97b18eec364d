#include "scene/ImageHeader.h"

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
// height, width. Markers without a payload: SOI D8, TEM 01, RST0-7 D0-D7.
void readJpeg(const unsigned char* b, std::size_t size, ImageHeader& out) {
    std::size_t pos = 2;
    while (pos + 1 < size) {
        if (b[pos] != 0xFF) return;
        const unsigned char marker = b[pos + 1];
        if (marker == 0xFF) { // fill byte
            ++pos;
            continue;
        }
        pos += 2;
        if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;
        if (marker == 0xD9 || marker == 0xDA || pos + 2 > size) return; // end or scan data
        const std::uint32_t length = bigEndian16(b + pos);
        if (length < 2) return;
        const bool startOfFrame =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (startOfFrame) {
            if (length < 7 || pos + 7 > size) return;
            out.height = bigEndian16(b + pos + 3);
            out.width = bigEndian16(b + pos + 5);
            return;
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
