#pragma once
// Immutable-storage textures (2D, 2D array and 3D) with the sampling state set at creation.
#include "gl/GlObject.h"
#include "gl/TextureFormat.h"

#include <string>

namespace pb::gl {

enum class Filter { Nearest, Linear, LinearMipmap };
enum class Wrap { Clamp, Repeat };

struct TextureDesc {
    TextureFormat format = TextureFormat::RGBA8;
    int width = 1, height = 1;
    int layers = 0;   // 0 = GL_TEXTURE_2D, >= 1 = GL_TEXTURE_2D_ARRAY
    bool volume = false; // with layers >= 1: GL_TEXTURE_3D (depth = layers), filtered in 3D
    int levels = 1;   // mip levels; 0 = full chain
    Filter filter = Filter::Linear;
    Wrap wrap = Wrap::Clamp;
    bool depthCompare = false; // shadow sampler (depth formats)
};

class Texture {
public:
    Texture() = default;
    explicit Texture(const TextureDesc& desc);

    // Uploads one mip level of the whole texture (all layers for arrays). `data` holds texels
    // in the format's transfer format/type, or 4x4 blocks for compressed formats.
    void upload(const void* data, int level = 0);
    void uploadLayer(int layer, const void* data, int level = 0);
    void generateMipmaps();
    void bind(int unit) const;
    // A name a GL capture shows (gl/DebugLabels.h).
    void label(const std::string& name) const;

    GLenum target() const {
        return desc_.layers <= 0 ? GL_TEXTURE_2D : desc_.volume ? GL_TEXTURE_3D : GL_TEXTURE_2D_ARRAY;
    }
    const TextureDesc& desc() const { return desc_; }
    GLuint id() const { return id_.id(); }
    std::size_t bytes() const;
    explicit operator bool() const { return bool(id_); }

private:
    TextureId id_;
    TextureDesc desc_;
};

// A 2D texture read texel for texel (render targets, read-backs, data tables): no mips,
// nearest filtering, so a fetch never blends neighbouring values.
Texture nearestTexture(TextureFormat format, int width, int height);

} // namespace pb::gl
