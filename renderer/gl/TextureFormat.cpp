#include "gl/TextureFormat.h"

#include <array>

namespace pb::gl {

namespace {
constexpr GLenum kBc6hUnsigned = 0x8E8F; // GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT(_EXT)

const std::array<FormatInfo, 12> kFormats = {{
    {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 0, false, false, false, "rgba8"},
    {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 0, false, false, false, "srgb8_a8"},
    {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 0, false, false, false, "r8"},
    {GL_RG16F, GL_RG, GL_FLOAT, 4, 0, false, false, true, "rg16f"},
    {GL_RG32F, GL_RG, GL_FLOAT, 8, 0, false, false, true, "rg32f"},
    {GL_RGBA16F, GL_RGBA, GL_FLOAT, 8, 0, false, false, true, "rgba16f"},
    {GL_RGBA32F, GL_RGBA, GL_FLOAT, 16, 0, false, false, true, "rgba32f"},
    {GL_R11F_G11F_B10F, GL_RGB, GL_FLOAT, 4, 0, false, false, true, "r11g11b10f"},
    {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4, 0, true, false, true, "depth32f"},
    {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4, 0, true, true, false,
     "depth24_stencil8"},
    {GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, 8, 0, true, true,
     true, "depth32f_stencil8"},
    {kBc6hUnsigned, GL_RGB, GL_HALF_FLOAT, 0, 16, false, false, true, "bc6h"},
}};
} // namespace

const FormatInfo& formatInfo(TextureFormat f) { return kFormats[static_cast<size_t>(f)]; }

std::size_t textureBytes(TextureFormat f, int w, int h, int layers) {
    const FormatInfo& i = formatInfo(f);
    if (i.bytesPerBlock)
        return std::size_t((w + 3) / 4) * std::size_t((h + 3) / 4) * i.bytesPerBlock *
               std::size_t(layers);
    return std::size_t(w) * std::size_t(h) * i.bytesPerTexel * std::size_t(layers);
}

bool parseTextureFormat(const std::string& name, TextureFormat& out) {
    for (size_t k = 0; k < kFormats.size(); ++k)
        if (name == kFormats[k].name) {
            out = static_cast<TextureFormat>(k);
            return true;
        }
    return false;
}

} // namespace pb::gl
