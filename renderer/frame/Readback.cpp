#include "frame/Readback.h"

#include "gl/Framebuffer.h"

#include <cstring>

namespace pb::render {

namespace {
template <typename T>
void flipRows(std::vector<T>& pixels, int width, int height, int channels) {
    size_t row = size_t(width) * channels;
    std::vector<T> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        T* a = &pixels[size_t(y) * row];
        T* b = &pixels[size_t(height - 1 - y) * row];
        std::memcpy(tmp.data(), a, row * sizeof(T));
        std::memcpy(a, b, row * sizeof(T));
        std::memcpy(b, tmp.data(), row * sizeof(T));
    }
}
} // namespace

image::Image8 readRgba8(const gl::Texture& texture) {
    gl::Framebuffer fbo("readback", {&texture}, nullptr);
    image::Image8 img;
    img.width = texture.desc().width;
    img.height = texture.desc().height;
    img.pixels.resize(size_t(img.width) * img.height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    flipRows(img.pixels, img.width, img.height, 4);
    return img;
}

image::ImageF readFloat(const gl::Texture& texture) {
    gl::Framebuffer fbo("readback", {&texture}, nullptr);
    image::ImageF img;
    img.width = texture.desc().width;
    img.height = texture.desc().height;
    img.channels = 4;
    img.pixels.resize(size_t(img.width) * img.height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
    glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, img.pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    flipRows(img.pixels, img.width, img.height, 4);
    return img;
}

} // namespace pb::render
