#include "gl/Texture.h"

#include "core/Error.h"
#include "gl/DebugLabels.h"
#include "gl/TextureLimits.h"

#include <algorithm>
#include <cmath>

namespace pb::gl {

TextureId genTexture() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return TextureId(id);
}
BufferId genBuffer() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return BufferId(id);
}
FramebufferId genFramebuffer() {
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    return FramebufferId(id);
}
VertexArrayId genVertexArray() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return VertexArrayId(id);
}
QueryId genQuery() {
    GLuint id = 0;
    glGenQueries(1, &id);
    return QueryId(id);
}

namespace {
int fullMipChain(int w, int h) {
    return 1 + int(std::floor(std::log2(double(std::max(w, h)))));
}
} // namespace

Texture::Texture(const TextureDesc& desc) : desc_(desc) {
    if (std::string why = textureLimitProblem(desc, queryTextureLimits()); !why.empty())
        throw Error("a " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                    (desc.layers > 0 ? "x" + std::to_string(desc.layers) : std::string()) +
                    " texture: " + why);
    id_ = genTexture();
    if (desc_.levels <= 0) desc_.levels = fullMipChain(desc_.width, desc_.height);
    const FormatInfo& fi = formatInfo(desc_.format);
    GLenum t = target();
    glBindTexture(t, id_.id());
    if (t == GL_TEXTURE_2D)
        glTexStorage2D(t, desc_.levels, fi.internalFormat, desc_.width, desc_.height);
    else
        glTexStorage3D(t, desc_.levels, fi.internalFormat, desc_.width, desc_.height,
                       desc_.layers);
    GLint mag = desc_.filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
    GLint min = desc_.filter == Filter::Nearest  ? GL_NEAREST
                : desc_.filter == Filter::Linear ? GL_LINEAR
                                                 : GL_LINEAR_MIPMAP_LINEAR;
    GLint wrap = desc_.wrap == Wrap::Clamp ? GL_CLAMP_TO_EDGE : GL_REPEAT;
    glTexParameteri(t, GL_TEXTURE_MIN_FILTER, min);
    glTexParameteri(t, GL_TEXTURE_MAG_FILTER, mag);
    glTexParameteri(t, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(t, GL_TEXTURE_WRAP_T, wrap);
    if (t == GL_TEXTURE_3D) glTexParameteri(t, GL_TEXTURE_WRAP_R, wrap);
    glTexParameteri(t, GL_TEXTURE_MAX_LEVEL, desc_.levels - 1);
    if (desc_.depthCompare) {
        glTexParameteri(t, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(t, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    glBindTexture(t, 0);
}

void Texture::upload(const void* data, int level) {
    const FormatInfo& fi = formatInfo(desc_.format);
    int w = std::max(1, desc_.width >> level), h = std::max(1, desc_.height >> level);
    GLenum t = target();
    glBindTexture(t, id_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    int layers = std::max(1, desc_.layers);
    if (fi.bytesPerBlock) {
        auto size = GLsizei(textureBytes(desc_.format, w, h, layers));
        if (t == GL_TEXTURE_2D)
            glCompressedTexSubImage2D(t, level, 0, 0, w, h, fi.internalFormat, size, data);
        else
            glCompressedTexSubImage3D(t, level, 0, 0, 0, w, h, layers, fi.internalFormat, size,
                                      data);
    } else if (t == GL_TEXTURE_2D) {
        glTexSubImage2D(t, level, 0, 0, w, h, fi.format, fi.type, data);
    } else {
        glTexSubImage3D(t, level, 0, 0, 0, w, h, layers, fi.format, fi.type, data);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(t, 0);
}

void Texture::uploadLayer(int layer, const void* data, int level) {
    const FormatInfo& fi = formatInfo(desc_.format);
    int w = std::max(1, desc_.width >> level), h = std::max(1, desc_.height >> level);
    glBindTexture(GL_TEXTURE_2D_ARRAY, id_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (fi.bytesPerBlock)
        glCompressedTexSubImage3D(GL_TEXTURE_2D_ARRAY, level, 0, 0, layer, w, h, 1,
                                  fi.internalFormat, GLsizei(textureBytes(desc_.format, w, h)),
                                  data);
    else
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, level, 0, 0, layer, w, h, 1, fi.format, fi.type,
                        data);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void Texture::generateMipmaps() {
    glBindTexture(target(), id_.id());
    glGenerateMipmap(target());
    glBindTexture(target(), 0);
}

void Texture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target(), id_.id());
}

std::size_t Texture::bytes() const {
    if (!id_) return 0; // never created: no GPU memory
    std::size_t total = 0;
    for (int l = 0; l < desc_.levels; ++l)
        total += textureBytes(desc_.format, std::max(1, desc_.width >> l),
                              std::max(1, desc_.height >> l), std::max(1, desc_.layers));
    return total;
}

Texture nearestTexture(TextureFormat format, int width, int height) {
    TextureDesc d;
    d.format = format;
    d.width = width;
    d.height = height;
    d.filter = Filter::Nearest;
    return Texture(d);
}

void Texture::label(const std::string& name) const { labelObject(GL_TEXTURE, id(), name); }

} // namespace pb::gl
