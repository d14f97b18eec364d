#pragma once
// The one place that maps probebench's texture formats to GL enums (and sizes), so passes and
// profiles talk about formats by name and never about GL constants.
#include <cstddef>
#include <glad/gl.h>
#include <string>

namespace pb::gl {

enum class TextureFormat {
    RGBA8,
    SRGB8_A8,
    R8,
    RG16F,
    RG32F,
    RGBA16F,
    RGBA32F,
    R11G11B10F,
    Depth32F,
    Depth24Stencil8,
    Depth32FStencil8,
    BC6H_UF16, // GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT
};

struct FormatInfo {
    GLenum internalFormat;
    GLenum format;      // pixel transfer format for uploads
    GLenum type;        // pixel transfer type for uploads
    std::size_t bytesPerTexel; // 0 for block-compressed formats
    std::size_t bytesPerBlock; // 4x4 block size for compressed formats, else 0
    bool isDepth;
    bool hasStencil;
    bool isFloat;
    const char* name;
};

const FormatInfo& formatInfo(TextureFormat f);
// Bytes a w x h x layers image takes on the GPU (compressed formats by 4x4 blocks).
std::size_t textureBytes(TextureFormat f, int w, int h, int layers = 1);
// Parses the names used in profiles and on the command line ("rgba16f", "r11g11b10f", ...).
bool parseTextureFormat(const std::string& name, TextureFormat& out);

} // namespace pb::gl
