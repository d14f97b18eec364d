#pragma once
// CPU images: linear float RGB(A) for HDR radiance and GI, 8-bit RGBA for displayable output.
// Rows are stored top to bottom (as image files are); GL read-back is flipped on the way in.
#include <cstdint>
#include <string>
#include <vector>

namespace pb::image {

struct ImageF {
    int width = 0, height = 0, channels = 4;
    std::vector<float> pixels; // width*height*channels
    float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

struct Image8 {
    int width = 0, height = 0; // always RGBA
    std::vector<std::uint8_t> pixels;
    std::uint8_t at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * 4 + c]; }
};

// Writers go through a temporary file and a rename: a failure never leaves a partial file.
// They throw pb::Error naming the path.
void writePng(const std::string& path, const Image8& img);
void writePfm(const std::string& path, const ImageF& img); // colour PFM (RGB), little endian
Image8 readPng(const std::string& path);
ImageF readPfm(const std::string& path);

} // namespace pb::image
