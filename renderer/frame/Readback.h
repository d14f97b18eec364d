#pragma once
// Reading GPU images back into CPU images (rows flipped to top-to-bottom).
#include "gl/Texture.h"
#include "image/Image.h"

namespace pb::render {

image::Image8 readRgba8(const gl::Texture& texture);   // 8-bit formats (RGBA8, sRGB8_A8, R8)
image::ImageF readFloat(const gl::Texture& texture);   // float formats, as RGBA32F values

} // namespace pb::render
