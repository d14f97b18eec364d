#include "image/Image.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>
// PNGs are read with libpng (as glTF textures are, renderer/scene/ImageDecode.h): `compare`
// reads files users hand it, and stb_image is not made for hostile files.
#include <png.h>

namespace pb::image {

void writePng(const std::string& path, const Image8& img) {
    if (img.width <= 0 || img.height <= 0) throw fileError(path, "empty image");
    std::vector<unsigned char> encoded;
    auto sink = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<unsigned char>*>(ctx);
        v->insert(v->end(), (unsigned char*)data, (unsigned char*)data + size);
    };
    if (!stbi_write_png_to_func(sink, &encoded, img.width, img.height, 4, img.pixels.data(),
                                img.width * 4))
        throw fileError(path, "PNG encoding failed");
    writeFileAtomic(path, encoded.data(), encoded.size());
}

void writePfm(const std::string& path, const ImageF& img) {
    if (img.width <= 0 || img.height <= 0) throw fileError(path, "empty image");
    std::ostringstream header;
    header << "PF\n" << img.width << " " << img.height << "\n-1.0\n"; // negative: little endian
    std::string bytes = header.str();
    size_t headerSize = bytes.size();
    bytes.resize(headerSize + size_t(img.width) * img.height * 3 * sizeof(float));
    float* dst = reinterpret_cast<float*>(bytes.data() + headerSize);
    // PFM stores rows bottom to top.
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float v = c < img.channels ? img.at(x, img.height - 1 - y, c) : 0.0f;
                std::memcpy(dst++, &v, sizeof(float));
            }
    writeFileAtomic(path, bytes.data(), bytes.size());
}

Image8 readPng(const std::string& path) {
    // Larger than any frame this tool writes (4096x4096 is the stress sweep's largest); the
    // size is checked from the header before a pixel is allocated.
    constexpr std::uint32_t kMaxSide = 16384;
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    // The simplified API reports errors as a message, never by a longjmp through this frame.
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        throw fileError(path, std::string("cannot read PNG: ") + png.message);
    if (png.width == 0 || png.height == 0 || png.width > kMaxSide || png.height > kMaxSide) {
        const std::string size = std::to_string(png.width) + "x" + std::to_string(png.height);
        png_image_free(&png);
        throw fileError(path, "PNG of " + size + " pixels: empty or larger than " +
                                  std::to_string(kMaxSide) + " on a side");
    }
    png.format = PNG_FORMAT_RGBA;
    Image8 img;
    img.width = int(png.width);
    img.height = int(png.height);
    img.pixels.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, img.pixels.data(), 0, nullptr))
        throw fileError(path, std::string("cannot read PNG: ") + png.message);
    return img;
}

ImageF readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw fileError(path, "cannot open");
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();
    if (!in || (magic != "PF" && magic != "Pf") || w <= 0 || h <= 0 || w > 65536 || h > 65536)
        throw fileError(path, "not a PFM file");
    int ch = magic == "PF" ? 3 : 1;
    std::vector<float> raw(size_t(w) * h * ch);
    in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size() * sizeof(float)));
    if (!in) throw fileError(path, "truncated PFM data");
    if (scale > 0) // big endian
        for (float& f : raw) {
            uint32_t u;
            std::memcpy(&u, &f, 4);
            u = __builtin_bswap32(u);
            std::memcpy(&f, &u, 4);
        }
    ImageF img;
    img.width = w;
    img.height = h;
    img.channels = ch;
    img.pixels.resize(raw.size());
    for (int y = 0; y < h; ++y)
        std::memcpy(&img.pixels[size_t(h - 1 - y) * w * ch], &raw[size_t(y) * w * ch],
                    size_t(w) * ch * sizeof(float));
    return img;
}

} // namespace pb::image
