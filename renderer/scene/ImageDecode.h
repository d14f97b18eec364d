#pragma once
// glTF textures decoded with libpng and libjpeg-turbo instead of stb_image: the fuzzers found
// memory corruption and undefined behaviour in Debian's stb_image (2022-09) on corrupt JPEGs
// (a Huffman table overflowing a fixed array, shifts by negative amounts), and stb itself is
// not made for hostile files. libpng and libjpeg-turbo are, and are fuzzed continuously
// upstream (OSS-Fuzz). Sizes are checked again from the decoder's own header parse.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pb::scene {

struct Rgba8Image {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> pixels; // width * height * 4, rows top to bottom
};

// Decodes a PNG or JPEG (chosen by its signature) to 8-bit RGBA. Returns "" or the problem;
// images wider or taller than `maxSide`, or with more than `maxPixels`, are refused before
// their pixels are allocated.
std::string decodeImageRgba8(const unsigned char* bytes, std::size_t size, std::uint32_t maxSide,
                             std::uint64_t maxPixels, Rgba8Image& out);

} // namespace pb::scene
