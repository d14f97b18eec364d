#pragma once
// The size an image file declares, read from its header without decoding it: glTF images are
// checked before a decoder is given them, so that a few hostile bytes cannot make it allocate
// gigabytes for a declared 60000 x 60000 picture, and nothing but PNG or JPEG (the two formats
// core glTF allows) ever reaches the decoder.
#include <cstddef>
#include <cstdint>

namespace pb::scene {

struct ImageHeader {
    enum class Kind { Unknown, Png, Jpeg };
    Kind kind = Kind::Unknown;
    // 0 when the header is cut off or has no size (a JPEG without a frame header).
    std::uint32_t width = 0, height = 0;
};

ImageHeader readImageHeader(const unsigned char* bytes, std::size_t size);

} // namespace pb::scene
